package org.kdtree.testing;

import org.kdtree.geom.SplitPlane;
import org.kdtree.kdtree.BuildContext;
import org.kdtree.kdtree.BuildNode;
import org.kdtree.kdtree.KdTreeBuilder;

/** A sound builder known only through a plug-in jar (the workbench's robot test): voxel midpoints, cycling axes. */
public class PluginMidpointBuilder extends KdTreeBuilder {
    @Override public String name() { return "plugin-midpoint"; }
    @Override protected boolean terminate(BuildContext c, BuildNode n) { return n.size() <= 2 || n.depth() >= c.depthCap(); }
    @Override protected SplitPlane findPlane(BuildContext c, BuildNode n) {
        int axis = n.depth() % n.dimension();
        return new SplitPlane(axis, n.voxel().min(axis) + 0.5 * n.voxel().extent(axis));
    }
}
