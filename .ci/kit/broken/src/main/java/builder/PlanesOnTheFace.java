package builder;

import org.kdtree.geom.SplitPlane;
import org.kdtree.kdtree.BuildContext;
import org.kdtree.kdtree.BuildNode;
import org.kdtree.kdtree.KdTreeBuilder;

/** CI's useless answer: valid, but every plane lies on the voxel's face (the quality tier must say it separates nothing). */
public class PlanesOnTheFace extends KdTreeBuilder {
    @Override public String name() {
        return "planes-on-the-face";
    }

    @Override protected boolean terminate(BuildContext context, BuildNode node) {
        return node.size() <= 2;
    }

    @Override protected SplitPlane findPlane(BuildContext context, BuildNode node) {
        int axis = node.depth() % node.dimension();
        return new SplitPlane(axis, node.voxel().max(axis));
    }
}
