package org.kdtree.testing;

import org.kdtree.geom.SplitPlane;
import org.kdtree.kdtree.BuildContext;
import org.kdtree.kdtree.BuildNode;
import org.kdtree.kdtree.KdTreeBuilder;

/** A broken student's builder for plug-in tests: terminate never returns (it ignores interruption too). */
public class LoopingTerminateBuilder extends KdTreeBuilder {
    @Override public String name() { return "loops-in-terminate"; }
    @Override protected boolean terminate(BuildContext c, BuildNode n) {
        Spin.forever();
        return true;
    }
    @Override protected SplitPlane findPlane(BuildContext c, BuildNode n) { return new SplitPlane(0, n.voxel().min(0)); }
}
