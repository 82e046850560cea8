package org.kdtree.testing;

import org.kdtree.geom.SplitPlane;
import org.kdtree.kdtree.BuildContext;
import org.kdtree.kdtree.BuildNode;
import org.kdtree.kdtree.KdTreeBuilder;

/** A broken student's builder for plug-in tests: its plane's position is 0 / 0. */
public class NaNPlaneBuilder extends KdTreeBuilder {
    @Override public String name() { return "nan-plane"; }
    @Override protected boolean terminate(BuildContext c, BuildNode n) { return n.size() <= 2; }
    @Override protected SplitPlane findPlane(BuildContext c, BuildNode n) {
        double empty = 0;
        return new SplitPlane(0, empty / empty);
    }
}
