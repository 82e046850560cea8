package org.kdtree.testing;

import org.kdtree.geom.SplitPlane;
import org.kdtree.kdtree.BuildContext;
import org.kdtree.kdtree.BuildNode;
import org.kdtree.kdtree.KdTreeBuilder;

/** A broken student's builder for plug-in tests: findPlane never returns (it ignores interruption too). */
public class LoopingFindPlaneBuilder extends KdTreeBuilder {
    @Override public String name() { return "loops-in-findplane"; }
    @Override protected boolean terminate(BuildContext c, BuildNode n) { return n.size() <= 2; }
    @Override protected SplitPlane findPlane(BuildContext c, BuildNode n) {
        Spin.forever();
        return null;
    }
}
