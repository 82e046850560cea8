package org.kdtree.kdtree;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;
import org.kdtree.accel.TriangleIntersector;
import org.kdtree.shape.TriangleMesh;
import org.kdtree.spec.Builders;

/**
 * The kd-tree's tracing layout (the mesh's corners, {@link KdTree#corners}): made with the tree,
 * not on the first query, and counted in the memory the statistics report.
 */
class TracingLayoutTest {
    @Test void theCornersAreMadeWithTheTreeBitForBit() {
        TriangleMesh sphere = Scenes.sphere(0.1, 0.2, -0.3, 1, 12, 24);
        KdTree tree = Builders.create("sah").build(sphere);
        double[] corners = TriangleIntersector.corners(sphere);
        assertThat(tree.corners).as("made with the tree, before any query").hasSize(9 * sphere.size());
        for (int k = 0; k < corners.length; k++)
            assertThat(Double.doubleToRawLongBits(tree.corners[k])).as("coordinate %d", k).isEqualTo(Double.doubleToRawLongBits(corners[k]));
    }

    @Test void theStatisticsCountIt() {
        TriangleMesh cube = Scenes.gridCube(3, 1);
        KdTree tree = Builders.create("sah").build(cube);
        long arrays = 2 * 16 + 4L * tree.nodes.length + 4L * tree.refs.length;
        assertThat(tree.memoryBytes()).isEqualTo(arrays + 16 + 72L * cube.size());
        assertThat(tree.stats().memoryBytes()).isEqualTo(tree.memoryBytes());
    }

    @Test void aSavedTreeLoadedAgainHasItToo() {
        TriangleMesh cube = Scenes.gridCube(3, 1);
        KdTree tree = Builders.create("sah").build(cube);
        KdTree restored = KdTree.restore(cube, tree.bounds(), tree.costModel(), tree.builderName(), tree.nodeArray(), tree.refArray(),
                tree.budgetLeaves(), tree.stats());
        assertThat(restored.corners).containsExactly(tree.corners);
        assertThat(restored.stats()).isEqualTo(tree.stats());
    }
}
