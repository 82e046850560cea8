package org.kdtree.testing;

import org.kdtree.build.BuildContext;
import org.kdtree.build.BuildNode;
import org.kdtree.build.KdTreeBuilder;
import org.kdtree.geom.SplitPlane;

/** A broken student's builder for plug-in tests: its plane's position is 0 / 0. */
public class NaNPlaneBuilder extends KdTreeBuilder {
    @Override public String name() { return "nan-plane"; }
    @Override protected boolean terminate(BuildContext c, BuildNode n) { return n.size() <= 2; }
    @Override protected SplitPlane findPlane(BuildContext c, BuildNode n) {
        double empty = 0;
        return new SplitPlane(0, empty / empty);
    }
}
