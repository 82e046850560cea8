package builder;

import org.kdtree.geom.SplitPlane;
import org.kdtree.kdtree.BuildContext;
import org.kdtree.kdtree.BuildNode;
import org.kdtree.kdtree.KdTreeBuilder;

/** CI's known-good answer to the starter: the median plane, cycling the axes, two objects a leaf. */
public class MyBuilder extends KdTreeBuilder {
    @Override public String name() {
        return "my-builder";
    }

    @Override protected boolean terminate(BuildContext context, BuildNode node) {
        return node.size() <= 2 || node.depth() >= context.depthCap();
    }

    @Override protected SplitPlane findPlane(BuildContext context, BuildNode node) {
        int axis = node.depth() % node.dimension();
        return new SplitPlane(axis, node.voxel().min(axis) + 0.5 * node.voxel().extent(axis));
    }
}
