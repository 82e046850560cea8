package org.kdtree.kdtree;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;
import org.kdtree.accel.CostModel;
import org.kdtree.accel.TreeStats;
import org.kdtree.geom.Box;

class KdTreeWriterTest {
    /** Writes: split x=1 -> leaf{0}, split y=2 -> leaf{1,2}, leaf{}. */
    private static void writeSample(KdTreeWriter w) {
        int root = w.interior(0, 1);
        w.leaf(new int[] {0}, 1);
        w.setRightChild(root);
        int inner = w.interior(1, 2);
        w.leaf(new int[] {1, 2}, 2);
        w.setRightChild(inner);
        w.leaf(new int[0], 0);
    }

    @Test void depthFirstLayoutWithRightChildIndices() {
        KdTreeWriter w = new KdTreeWriter(2);
        writeSample(w);
        KdTree t = w.finish(points(2), Box.of2(0, 0, 4, 4), CostModel.WALD_HAVRAN, "test");
        assertThat(t.nodeCount()).isEqualTo(5);
        assertThat(t.isLeaf(0)).isFalse();
        assertThat(t.axis(0)).isZero();
        assertThat(t.split(0)).isEqualTo(1);
        assertThat(t.leafPrimitives(t.leftChild(0))).containsExactly(0);
        int inner = t.rightChild(0);
        assertThat(t.axis(inner)).isEqualTo(1);
        assertThat(t.leafPrimitives(t.leftChild(inner))).containsExactly(1, 2);
        assertThat(t.leafPrimitives(t.rightChild(inner))).isEmpty();
        TreeStats s = t.stats();
        assertThat(s.leaves()).isEqualTo(3);
        assertThat(s.emptyLeaves()).isEqualTo(1);
        assertThat(s.references()).isEqualTo(3);
        assertThat(s.maxDepth()).isEqualTo(2);
        assertThat(s.averageRefsPerLeaf()).isEqualTo(1.5);
    }

    @Test void expectedCostFollowsTheRecursiveFormula() {
        KdTreeWriter w = new KdTreeWriter(2);
        writeSample(w);
        KdTree t = w.finish(points(2), Box.of2(0, 0, 4, 4), new CostModel(15, 20), "test");
        // perimeters: root 16; left [0,1]x[0,4] 10; right [1,4]x[0,4] 14; its children [1,4]x[0,2] 10 and [1,4]x[2,4] 10
        double right = 15 + 10.0 / 14 * (2 * 20) + 10.0 / 14 * 0;
        double expected = 15 + 10.0 / 16 * (1 * 20) + 14.0 / 16 * right;
        assertThat(t.stats().expectedCost()).isCloseTo(expected, org.assertj.core.data.Offset.offset(1e-9));
    }

    @Test void appendSplicesASubtreeWrittenElsewhere() {
        KdTreeWriter sub = new KdTreeWriter(2);
        writeSample(sub);
        KdTreeWriter w = new KdTreeWriter(2);
        int root = w.interior(0, 0.5);
        w.leaf(new int[] {7}, 1);
        w.setRightChild(root);
        w.append(sub);
        KdTree t = w.finish(points(2), Box.of2(0, 0, 4, 4), CostModel.WALD_HAVRAN, "test");
        int r = t.rightChild(0);
        assertThat(t.split(r)).isEqualTo(1);
        assertThat(t.leafPrimitives(t.leftChild(r))).containsExactly(0);
        int inner = t.rightChild(r);
        assertThat(t.leafPrimitives(t.leftChild(inner))).containsExactly(1, 2);
        assertThat(t.leafPrimitives(t.rightChild(inner))).isEmpty();
        assertThat(t.leafPrimitives(1)).containsExactly(7);
    }

    /** Writes a chain of {@code n} interior nodes on cycling axes, each with a leaf on its left, below a node already written. */
    private static void writeChain(KdTreeWriter w, int n, int dimension) {
        int[] prims = {3, 1, 4, 1, 5};
        for (int i = 0; i < n; i++) {
            int node = w.interior(i % dimension, i * 0.1 - 7);
            w.leaf(prims, i % 3, i % 3);
            w.setRightChild(node);
        }
        w.leaf(prims, 2);
    }

    /** Splicing moves children and references and keeps planes to the bit, also when the writer's arrays grow meanwhile. */
    @Test void anAppendedSubtreeIsTheTreeWrittenInOnePiece() {
        for (int k : new int[] {2, 3, 64}) {
            KdTreeWriter whole = new KdTreeWriter(k), top = new KdTreeWriter(k), sub = new KdTreeWriter(k);
            for (KdTreeWriter w : new KdTreeWriter[] {whole, top}) {
                int root = w.interior(k - 1, -0.0);
                w.leaf(new int[] {9, 8}, 2);
                w.setRightChild(root);
            }
            writeChain(whole, 200, k);
            writeChain(sub, 200, k);
            top.append(sub);
            double[] lo = new double[k], hi = new double[k];
            java.util.Arrays.fill(hi, 1);
            KdTree expected = whole.finish(points(lo.length), new Box(lo, hi), CostModel.WALD_HAVRAN, "whole");
            KdTree spliced = top.finish(points(lo.length), new Box(lo, hi), CostModel.WALD_HAVRAN, "spliced");
            assertThat(spliced.nodeArray()).as("%d-D nodes", k).isEqualTo(expected.nodeArray());
            assertThat(spliced.refArray()).as("%d-D references", k).isEqualTo(expected.refArray());
            int last = Nodes.rightChild(Nodes.word(spliced.nodeArray(), spliced.nodeCount() - 3), spliced.axisBits());
            assertThat(Nodes.isLeaf(Nodes.word(spliced.nodeArray(), last), spliced.axisBits())).isTrue();
            assertThat(spliced.leafPrimitives(last)).containsExactly(3, 1);
        }
    }

    @Test void theAxisFieldIsAsWideAsTheDimensionNeeds() {
        assertThat(Nodes.axisBits(1)).isEqualTo(1);
        assertThat(Nodes.axisBits(3)).isEqualTo(2);
        assertThat(Nodes.axisBits(31)).isEqualTo(5);
        assertThat(Nodes.axisBits(32)).isEqualTo(6);
        assertThat(Nodes.axisBits(64)).isEqualTo(7);
        assertThat(Nodes.maxNode(3)).isEqualTo((1 << 29) - 1);
        assertThat(Nodes.maxNode(64)).isEqualTo((1 << 24) - 1);
        org.assertj.core.api.Assertions.assertThatThrownBy(() -> Nodes.axisBits(65)).hasMessageContaining("1 to 64 dimensions");
    }

    @Test void aSixtyFourDimensionalTreeKeepsItsLastAxisApartFromItsLeaves() {
        double[] lo = new double[64], hi = new double[64];
        java.util.Arrays.fill(hi, 1);
        KdTreeWriter w = new KdTreeWriter(64);
        int root = w.interior(63, 0.5);
        w.leaf(new int[] {0}, 1);
        w.setRightChild(root);
        w.leaf(new int[] {1}, 1);
        KdTree t = w.finish(points(lo.length), new Box(lo, hi), CostModel.WALD_HAVRAN, "test");
        assertThat(t.isLeaf(0)).isFalse();
        assertThat(t.axis(0)).isEqualTo(63);
        assertThat(t.leafPrimitives(t.rightChild(0))).containsExactly(1);
        org.assertj.core.api.Assertions.assertThatThrownBy(() -> new KdTreeWriter(64).interior(64, 0))
                .hasMessageContaining("out of range");
    }

    @Test void aNodeTakesTwelveBytesAndKeepsItsPlaneToTheBit() {
        KdTreeWriter w = new KdTreeWriter(2);
        int root = w.interior(0, 0.1);           // no float: a 4-byte plane could not hold it
        w.leaf(new int[] {0}, 1);
        w.setRightChild(root);
        int inner = w.interior(1, -0.0);
        w.leaf(new int[] {1, 2}, 2);
        w.setRightChild(inner);
        w.leaf(new int[0], 0);
        KdTree t = w.finish(points(2), Box.of2(-1, -1, 4, 4), CostModel.WALD_HAVRAN, "test");
        assertThat(t.split(0)).isEqualTo(0.1);
        assertThat(Double.doubleToRawLongBits(t.split(t.rightChild(0)))).isEqualTo(Double.doubleToRawLongBits(-0.0));
        assertThat(Nodes.split(t.nodeArray(), 0)).isEqualTo(0.1);
        assertThat(t.memoryBytes()).isEqualTo(2 * 16 + 12L * 5 + 4L * 3);
        assertThat(t.leafStart(t.leftChild(t.rightChild(0)))).isEqualTo(1);
        assertThat(t.leafSize(t.leftChild(t.rightChild(0)))).isEqualTo(2);
    }

    /** Points of dimension {@code k} for a hand-written tree to be over (ten of them: the samples reference indices 0 to 9). */
    private static org.kdtree.shape.PointsKd points(int k) {
        return new org.kdtree.shape.PointsKd(k, new double[10 * k]);
    }
}
