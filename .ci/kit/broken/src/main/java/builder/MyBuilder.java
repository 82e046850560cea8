package builder;

import org.kdtree.geom.SplitPlane;
import org.kdtree.kdtree.BuildContext;
import org.kdtree.kdtree.BuildNode;
import org.kdtree.kdtree.KdTreeBuilder;

/** CI's broken answer: its plane lies beyond the voxel (the contract must say "outside the voxel"). */
public class MyBuilder extends KdTreeBuilder {
    @Override public String name() {
        return "my-builder";
    }

    @Override protected boolean terminate(BuildContext context, BuildNode node) {
        return node.size() <= 2;
    }

    @Override protected SplitPlane findPlane(BuildContext context, BuildNode node) {
        return new SplitPlane(0, node.voxel().max(0) + 1);
    }
}
