package org.kdtree.kdtree;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;
import org.kdtree.accel.TriangleIntersector;
import org.kdtree.shape.TriangleMesh;
import org.kdtree.spec.Builders;

/**
 * The kd-tree's tracing layout ({@link LeafCorners}): made with the tree, each reference's
 * triangle copied in leaf order, and counted in the memory the statistics report.
 */
class LeafCornersTest {
    @Test void everyReferenceHasItsTrianglesCornersInLeafOrder() {
        TriangleMesh sphere = Scenes.sphere(0.1, 0.2, -0.3, 1, 12, 24);
        KdTree tree = Builders.create("sah").build(sphere);
        double[] corners = TriangleIntersector.corners(sphere);
        assertThat(tree.refs.length).as("triangles that straddle planes are referenced more than once").isGreaterThan(sphere.size());
        assertThat(tree.leafCorners).hasSize(9 * tree.refs.length);
        for (int r = 0; r < tree.refs.length; r++)
            for (int k = 0; k < 9; k++)
                assertThat(Double.doubleToRawLongBits(tree.leafCorners[9 * r + k]))
                        .as("reference %d, coordinate %d", r, k).isEqualTo(Double.doubleToRawLongBits(corners[9 * tree.refs[r] + k]));
    }

    @Test void theStatisticsCountIt() {
        KdTree tree = Builders.create("sah").build(Scenes.gridCube(3, 1));
        long arrays = 2 * 16 + 4L * tree.nodes.length + 4L * tree.refs.length;
        assertThat(tree.memoryBytes()).isEqualTo(arrays + 16 + 72L * tree.refs.length);
        assertThat(tree.stats().memoryBytes()).isEqualTo(tree.memoryBytes());
    }

    @Test void aSavedTreeLoadedAgainHasItToo() {
        TriangleMesh cube = Scenes.gridCube(3, 1);
        KdTree tree = Builders.create("sah").build(cube);
        KdTree restored = KdTree.restore(cube, tree.bounds(), tree.costModel(), tree.builderName(), tree.nodeArray(), tree.refArray(),
                tree.budgetLeaves(), tree.stats());
        assertThat(restored.leafCorners).containsExactly(tree.leafCorners);
        assertThat(restored.stats()).isEqualTo(tree.stats());
    }
}
