package org.kdtree.check;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;
import org.kdtree.geom.Box;
import org.kdtree.io.BundledScenes;
import org.kdtree.kdtree.KdTree;
import org.kdtree.kdtree.MedianPlaneBuilder;
import org.kdtree.kdtree.ObjectMedianBuilder;
import org.kdtree.kdtree.SahBuilder;
import org.kdtree.shape.Scene2D;

/** The handful of 2-D objects of the talk's figures 2-5 give the splits the talk describes. */
class TalkFiguresTest {
    private final Scene2D scene = BundledScenes.read2D("talk-figures.scene2d");

    @Test void figure2MedianPlanesCutEveryVoxelInItsMiddleCyclingTheAxes() {
        KdTree tree = new MedianPlaneBuilder().minPrimitives(1).build(scene);
        TreeInspector in = new TreeInspector(tree);
        assertThat(in.interiors()).isNotEmpty();
        for (TreeInspector.Interior n : in.interiors()) {
            assertThat(n.axis()).as("axis at depth %d", n.depth()).isEqualTo(n.depth() % 2);
            Box v = n.voxel();
            assertThat(n.split()).isEqualTo(0.5 * (v.min(n.axis()) + v.max(n.axis())));
        }
        // the scene box is [1, 9.4] x [1, 9]: first cut x = 5.2, then y = 5 on both sides
        assertThat(tree.split(0)).isEqualTo(5.2);
        assertThat(tree.split(1)).isEqualTo(5.0);
        assertThat(tree.split(tree.rightChild(0))).isEqualTo(5.0);
    }

    @Test void figure3ObjectMedianSplitsThroughTheMedianObjectAndBalancesTheChildren() {
        KdTree tree = new ObjectMedianBuilder().minPrimitives(1).build(scene);
        // object centres on x: 1.5, 3.25, 6.25, 8.3, 9, 9.1: the lower median is the long segment's 6.25
        assertThat(tree.axis(0)).isEqualTo(0);
        assertThat(tree.split(0)).isEqualTo(6.25);
        TreeInspector in = new TreeInspector(tree);
        for (TreeInspector.Interior n : in.interiors()) assertThat(n.axis()).isEqualTo(n.depth() % 2);
        // the median object straddles the plane and goes to both sides: 3 objects left, 4 right
        int[] counts = countBelow(tree, 0);
        assertThat(counts[0]).isEqualTo(3);
        assertThat(counts[1]).isEqualTo(4);
    }

    @Test void figure4SahPlanesLieOnObjectBoundsAndCostLessThanTheMedianTrees() {
        KdTree sah = new SahBuilder().build(scene);
        TreeInspector in = new TreeInspector(sah);
        Box clip = new Box(2);
        for (TreeInspector.Interior n : in.interiors()) {
            boolean onABound = false;
            for (int i = 0; i < scene.size(); i++) {
                scene.clip(i, n.voxel(), clip);
                if (!clip.isEmpty() && (clip.min(n.axis()) == n.split() || clip.max(n.axis()) == n.split())) onABound = true;
            }
            assertThat(onABound).as("SAH plane %s=%s lies on an object's bound", n.axis(), n.split()).isTrue();
        }
        double cost = sah.stats().expectedCost();
        assertThat(cost).isLessThan(new MedianPlaneBuilder().minPrimitives(1).build(scene).stats().expectedCost());
        assertThat(cost).isLessThan(new ObjectMedianBuilder().minPrimitives(1).build(scene).stats().expectedCost());
    }

    @Test void figure5FavouringEmptyVoxelsCutsOffMoreEmptySpace() {
        KdTree plain = new SahBuilder().lambda(1.0).build(scene);
        KdTree favoured = new SahBuilder().lambda(0.8).build(scene);
        assertThat(favoured.stats().emptyLeaves()).isGreaterThan(plain.stats().emptyLeaves());
        assertThat(emptyArea(favoured)).isGreaterThan(emptyArea(plain));
    }

    @Test void sahStopsWhereNoSplitBeatsALeaf() {
        KdTree tree = new SahBuilder().lambda(1.0).build(scene);
        // the two objects on the left share a leaf: separating them costs more than testing both
        TreeInspector in = new TreeInspector(tree);
        assertThat(in.leaves()).anySatisfy(l -> assertThat(l.refs()).containsExactlyInAnyOrder(0, 1));
    }

    private static double emptyArea(KdTree tree) {
        return new TreeInspector(tree).leaves().stream().filter(l -> l.refs().length == 0)
                .mapToDouble(l -> l.voxel().volume()).sum();
    }

    /** Primitives in the left and right subtrees of an interior node. */
    private static int[] countBelow(KdTree tree, int node) {
        return new int[] {distinct(tree, tree.leftChild(node)), distinct(tree, tree.rightChild(node))};
    }

    private static int distinct(KdTree tree, int node) {
        java.util.Set<Integer> s = new java.util.HashSet<>();
        collect(tree, node, s);
        return s.size();
    }

    private static void collect(KdTree tree, int node, java.util.Set<Integer> out) {
        if (tree.isLeaf(node)) {
            for (int r : tree.leafPrimitives(node)) out.add(r);
            return;
        }
        collect(tree, tree.leftChild(node), out);
        collect(tree, tree.rightChild(node), out);
    }
}
