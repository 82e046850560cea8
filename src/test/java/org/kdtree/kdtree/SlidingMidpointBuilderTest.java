package org.kdtree.kdtree;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.Random;
import org.junit.jupiter.api.Test;
import org.kdtree.accel.SharedSettings;
import org.kdtree.shape.PointsKd;
import org.kdtree.spec.Builders;

/** The sliding midpoint's own promises: no empty leaf, bounded trees on duplicates, small memory. */
class SlidingMidpointBuilderTest {
    /** 100,000 copies of 10 distinct 3-D points, in random order. */
    private static PointsKd tenPointsRepeated(int n) {
        Random r = new Random(1);
        double[] distinct = new double[30];
        for (int i = 0; i < distinct.length; i++) distinct[i] = r.nextDouble();
        double[] c = new double[3 * n];
        for (int i = 0; i < n; i++) System.arraycopy(distinct, 3 * r.nextInt(10), c, 3 * i, 3);
        return new PointsKd(3, c);
    }

    @Test void copiesOfTenPointsMakeTenLeaves() {
        KdTree tree = new SlidingMidpointBuilder().build(tenPointsRepeated(100_000));
        assertThat(tree.stats().leaves()).as("one leaf per distinct point").isEqualTo(10);
        assertThat(tree.nodeCount()).isEqualTo(19);
    }

    /**
     * The other builders on the same data: a point is never sent to both children, so the base
     * class's "separates nothing" rule never fires on points; what bounds them is the depth cap,
     * which stops each chain of copies after a few dozen levels.
     */
    @Test void everyBuilderStaysBoundedOnCopies() {
        PointsKd copies = tenPointsRepeated(100_000);
        for (String name : Builders.names()) {
            KdTreeBuilder b = Builders.create(name);
            KdTree tree = b.build(copies);
            int cap = b.depthCap(copies.size());
            assertThat(tree.nodeCount()).as(name + ": nodes over 10 distinct points (depth cap " + cap + ")")
                    .isLessThanOrEqualTo(4 * 10 * (cap + 1));
            assertThat(tree.stats().references()).as(name + ": each point listed once").isEqualTo(copies.size());
        }
    }

    @Test void noLeafIsEmptyAndNoneExceedsTheLeafSize() {
        Random r = new Random(2);
        double[] c = new double[2 * 5000];
        for (int i = 0; i < c.length; i++) c[i] = r.nextDouble() * (i % 2 == 0 ? 1000 : 1); // long and thin
        KdTree tree = new SlidingMidpointBuilder().leafSize(4).build(new PointsKd(2, c));
        for (int node = 0; node < tree.nodeCount(); node++) {
            if (!tree.isLeaf(node)) continue;
            assertThat(tree.leafSize(node)).as("leaf " + node).isBetween(1, 4);
        }
    }

    @Test void aMillionRandomPointsCostAtMostEightBytesEachBeyondThePoints() {
        Random r = new Random(3);
        int n = 1_000_000;
        double[] c = new double[3 * n];
        for (int i = 0; i < c.length; i++) c[i] = r.nextDouble();
        KdTree tree = new SlidingMidpointBuilder().build(new PointsKd(3, c));
        assertThat((double) tree.memoryBytes() / n).as("tree bytes per point (leaf size %d, %d leaves)",
                SharedSettings.LEAF_SIZE.defaultValue(), tree.stats().leaves()).isLessThanOrEqualTo(8.0);
    }

    @Test void leafSizeIsChecked() {
        assertThatThrownBy(() -> new SlidingMidpointBuilder().leafSize(0)).hasMessageContaining("leaf size must be between 1 and 65536");
    }
}
