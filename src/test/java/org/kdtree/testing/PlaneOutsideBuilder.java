package org.kdtree.testing;

import org.kdtree.geom.SplitPlane;
import org.kdtree.kdtree.BuildContext;
import org.kdtree.kdtree.BuildNode;
import org.kdtree.kdtree.KdTreeBuilder;

/** A broken student's builder for plug-in tests: its plane lies beyond the voxel. */
public class PlaneOutsideBuilder extends KdTreeBuilder {
    @Override public String name() { return "plane-outside"; }
    @Override protected boolean terminate(BuildContext c, BuildNode n) { return n.size() <= 2; }
    @Override protected SplitPlane findPlane(BuildContext c, BuildNode n) { return new SplitPlane(0, n.voxel().max(0) + 1); }
}
