package builder;

import org.kdtree.geom.SplitPlane;
import org.kdtree.kdtree.BuildContext;
import org.kdtree.kdtree.BuildNode;
import org.kdtree.kdtree.KdTreeBuilder;

/** CI's runaway answer: terminate() never says yes, only the depth cap stops it (the contract must say "never stops"). */
public class NeverStops extends KdTreeBuilder {
    @Override public String name() {
        return "never-stops";
    }

    @Override protected boolean terminate(BuildContext context, BuildNode node) {
        return false;
    }

    @Override protected SplitPlane findPlane(BuildContext context, BuildNode node) {
        int axis = node.depth() % node.dimension();
        return new SplitPlane(axis, node.voxel().min(axis) + 0.5 * node.voxel().extent(axis));
    }
}
