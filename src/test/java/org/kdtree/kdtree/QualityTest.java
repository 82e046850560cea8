package org.kdtree.kdtree;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;
import org.kdtree.generate.Meshes;
import org.kdtree.shape.TriangleMesh;

/** The quality presets: exact is the default tree; the others are shallower, smaller and cost a little more. */
class QualityTest {
    private static final TriangleMesh SPHERE = Meshes.surface(60, 90, 41);   // 10,800 triangles

    @Test void exactIsTheDefaultTree() {
        SahAlgorithmsTest.assertSameTree(new SahBuilder().quality(Quality.EXACT).build(SPHERE), new SahBuilder().build(SPHERE));
    }

    @Test void cheaperPresetsBuildSmallerTreesThatCostALittleMore() {
        KdTree exact = new SahBuilder().build(SPHERE);
        KdTree balanced = new SahBuilder().quality(Quality.BALANCED).build(SPHERE);
        KdTree fast = new SahBuilder().quality(Quality.FAST).build(SPHERE);
        assertThat(fast.nodeCount()).isLessThan(balanced.nodeCount());
        assertThat(balanced.nodeCount()).isLessThan(exact.nodeCount() / 2);
        double cost = exact.stats().expectedCost();
        assertThat(balanced.stats().expectedCost()).isLessThanOrEqualTo(1.05 * cost);
        assertThat(fast.stats().expectedCost()).isLessThanOrEqualTo(1.30 * cost);
    }

    @Test void aPresetSetsTheSearchAndTheLeafSizeAndWhatFollowsItWins() {
        SahBuilder b = new SahBuilder();
        b.maxDepth(12);
        b.quality(Quality.FAST);
        assertThat(b.algorithm()).isEqualTo(SahBuilder.Algorithm.EVENT);
        assertThat(b.leafBelow()).isEqualTo(11);
        assertThat(b.maxDepth()).isEqualTo(-1);
        assertThat(b.leafBelow(2).exactBelow(0).maxDepth(12).depthCap(1 << 16)).isEqualTo(12);
        assertThat(b.describeSettings()).contains("maxDepth=12").contains("leafBelow=2").contains("algorithm=event");
        assertThat(new SahBuilder().quality(Quality.BALANCED).describeSettings()).contains("algorithm=event").contains("leafBelow=6");
        assertThat(new SahBuilder().quality(Quality.EXACT).describeSettings()).doesNotContain("leafBelow");
        assertThatThrownBy(() -> new SahBuilder().leafBelow(0)).isInstanceOf(IllegalArgumentException.class)
                .hasMessageStartingWith("leaf below must be between 1 and 65536");
    }

    @Test void noNodeBelowTheLeafSizeIsSplit() {
        KdTree t = new SahBuilder().leafBelow(9).build(SPHERE);
        assertThat(t.nodeCount()).isLessThan(new SahBuilder().build(SPHERE).nodeCount());
        for (int node = 0; node < t.nodeCount(); node++)   // an inner node's T holds at least the primitives of its leaves
            if (!t.isLeaf(node)) assertThat(primitivesBelow(t, node).size()).as("inner node %d", node).isGreaterThanOrEqualTo(9);
    }

    private static java.util.Set<Integer> primitivesBelow(KdTree t, int node) {
        java.util.Set<Integer> s = new java.util.HashSet<>();
        java.util.ArrayDeque<Integer> todo = new java.util.ArrayDeque<>(java.util.List.of(node));
        while (!todo.isEmpty()) {
            int n = todo.pop();
            if (t.isLeaf(n)) for (int i = t.leafStart(n); i < t.leafEnd(n); i++) s.add(t.ref(i));
            else { todo.push(t.leftChild(n)); todo.push(t.rightChild(n)); }
        }
        return s;
    }
}
