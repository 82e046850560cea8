package org.kdtree.build;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;
import org.kdtree.shape.TriangleMesh;
import org.kdtree.tree.KdTree;
import org.kdtree.generate.Meshes;

/** The quality presets: exact is the default tree; the others are shallower, smaller and cost a little more. */
class QualityTest {
    private static final TriangleMesh SPHERE = Meshes.surface(60, 90, 41);   // 10,800 triangles

    @Test void exactIsTheDefaultTree() {
        SahAlgorithmsTest.assertSameTree(new SahBuilder().quality(Quality.EXACT).build(SPHERE), new SahBuilder().build(SPHERE));
    }

    @Test void cheaperPresetsBuildShallowerSmallerTreesThatCostMore() {
        KdTree exact = new SahBuilder().build(SPHERE);
        KdTree balanced = new SahBuilder().quality(Quality.BALANCED).build(SPHERE);
        KdTree fast = new SahBuilder().quality(Quality.FAST).build(SPHERE);
        int n = SPHERE.size();
        assertThat(balanced.stats().maxDepth()).isLessThanOrEqualTo((int) Math.round(8 + 1.0 * Math.log(n) / Math.log(2)));
        assertThat(fast.stats().maxDepth()).isLessThanOrEqualTo((int) Math.round(8 + 0.8 * Math.log(n) / Math.log(2)));
        assertThat(fast.nodeCount()).isLessThan(balanced.nodeCount());
        assertThat(balanced.nodeCount()).isLessThan(exact.nodeCount());
        double cost = exact.stats().expectedCost();
        assertThat(balanced.stats().expectedCost()).isBetween(cost, 1.15 * cost);
        assertThat(fast.stats().expectedCost()).isBetween(balanced.stats().expectedCost(), 1.5 * cost);
    }

    @Test void aPresetIsADepthCapAndAnExplicitCapStillWins() {
        SahBuilder b = new SahBuilder().quality(Quality.FAST);
        assertThat(b.algorithm()).isEqualTo(SahBuilder.Algorithm.EVENT);
        assertThat(b.depthCap(1 << 16)).isEqualTo(8 + 13);   // 8 + 0.8 * 16 = 20.8
        assertThat(b.maxDepth(12).depthCap(1 << 16)).isEqualTo(12);
        assertThat(b.describeSettings()).contains("maxDepth=12");
        assertThat(new SahBuilder().quality(Quality.BALANCED).describeSettings()).contains("auto(8+1.0 log2 N)");
        assertThatThrownBy(() -> new SahBuilder().depthFactor(-1)).isInstanceOf(IllegalArgumentException.class);
    }
}
