package org.kdtree.kdtree;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.BitSet;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.kdtree.generate.Meshes;
import org.kdtree.geom.Box;
import org.kdtree.io.BundledScenes;
import org.kdtree.shape.Primitives;
import org.kdtree.shape.TriangleMesh;

/**
 * Which splits of a built SAH tree were made past a local minimum ({@link SahBuilder#lookahead}),
 * read back from the tree and its cost model alone.
 */
class SplitsPastLocalMinimumTest {
    private static final double LAMBDA = new SahBuilder().lambda();

    /** The scene built to need a lookahead: its default tree is one leaf, lookahead 1's a subtree whose root split does not pay alone. */
    @Test void theSplitALookaheadMadeIsFoundAndNoneWithout() {
        TriangleMesh scene = LookaheadTest.twoCorners();
        KdTree none = new SahBuilder().build(scene), one = new SahBuilder().lookahead(1).build(scene);
        assertThat(SplitsPastLocalMinimum.of(none, LAMBDA).cardinality()).isZero();
        BitSet past = SplitsPastLocalMinimum.of(one, LAMBDA);
        assertThat(past.get(0)).as("the root's split, which does not beat the leaf of two").isTrue();
        assertThat(past.cardinality()).as("splits past a local minimum, along one path of one").isEqualTo(1);
    }

    /**
     * Without lookahead every split beats its leaf by construction: the function finds none on any
     * scene of the golden trees (the talk's figures, 2-D, 3-D, planar, degenerate and k-D scenes);
     * with a lookahead of 2 it finds some on generated meshes, and only interior nodes.
     */
    @Test void withoutLookaheadEverySplitBeatsItsLeaf() {
        for (Map.Entry<String, Primitives> s : SameTreesAsBeforeTest.scenes().entrySet()) {
            for (double lambda : new double[] {LAMBDA, 1.0}) {
                KdTree tree = new SahBuilder().lambda(lambda).build(s.getValue());
                assertThat(SplitsPastLocalMinimum.of(tree, lambda).cardinality()).as("%s, lambda %s", s.getKey(), lambda).isZero();
            }
            KdTree unclipped = new SahBuilder().perfectSplits(false).build(s.getValue());
            assertThat(SplitsPastLocalMinimum.of(unclipped, LAMBDA).cardinality()).as("%s, no perfect splits", s.getKey()).isZero();
        }
        KdTree two = new SahBuilder().lookahead(2).build(Meshes.clustered(3000, 0.02, 41));
        BitSet past = SplitsPastLocalMinimum.of(two, LAMBDA);
        assertThat(past.cardinality()).as("lookahead 2 on the clustered mesh").isPositive();
        for (int n = past.nextSetBit(0); n >= 0; n = past.nextSetBit(n + 1)) assertThat(two.isLeaf(n)).isFalse();
    }

    /**
     * The workbench's bundled 2-D scenes: on the talk's figures under Kt 15 and Ki 20 a lookahead
     * changes nothing (every trial is taken back), so none is marked; under Kt 30 and Ki 80, and on
     * the long thin object across a field of small ones, a lookahead of 1 keeps one split past a
     * local minimum, and its voxel is a leaf of the tree built without one.
     */
    @Test void onTheWorkbenchScenesTheMarkedSplitIsALeafWithoutLookahead() {
        Primitives talk = BundledScenes.read2D("talk-figures.scene2d");
        for (int n = 0; n <= 3; n++)
            assertThat(SplitsPastLocalMinimum.of(new SahBuilder().lookahead(n).build(talk), LAMBDA).cardinality()).as("talk, lookahead %d", n).isZero();
        assertOneMarkedSplitThatWasALeaf(talk, () -> new SahBuilder().costs(30, 80));
        assertOneMarkedSplitThatWasALeaf(BundledScenes.read2D("long-thin.scene2d"), SahBuilder::new);
    }

    private static void assertOneMarkedSplitThatWasALeaf(Primitives scene, java.util.function.Supplier<SahBuilder> builder) {
        KdTree none = builder.get().build(scene), one = builder.get().lookahead(1).build(scene);
        BitSet past = SplitsPastLocalMinimum.of(one, LAMBDA);
        assertThat(past.cardinality()).as("lookahead 1").isEqualTo(1);
        assertThat(SplitsPastLocalMinimum.of(none, LAMBDA).cardinality()).as("lookahead 0").isZero();
        assertThat(one.stats().expectedCost()).isLessThan(none.stats().expectedCost());
        List<Box> leavesWithout = voxels(none, false);
        for (Box v : voxels(one, true)) if (past.get(index(one, v))) assertThat(leavesWithout).as("the marked split's voxel").contains(v);
    }

    /** The voxels of a tree's interior nodes (or of its leaves), copied, in walk order. */
    private static List<Box> voxels(KdTree tree, boolean interior) {
        List<Box> out = new ArrayList<>();
        tree.walk(new TreeVisitor() {
            @Override public void interior(int node, int depth, Box voxel, int axis, double split) { if (interior) out.add(voxel.copy()); }
            @Override public void leaf(int node, int depth, Box voxel, int from, int to) { if (!interior) out.add(voxel.copy()); }
        });
        return out;
    }

    /** The interior node of {@code tree} whose voxel is {@code v}. */
    private static int index(KdTree tree, Box v) {
        int[] found = {-1};
        tree.walk(new TreeVisitor() {
            @Override public void interior(int node, int depth, Box voxel, int axis, double split) { if (voxel.equals(v)) found[0] = node; }
            @Override public void leaf(int node, int depth, Box voxel, int from, int to) { }
        });
        return found[0];
    }

    @Test void aSingleLeafHasNone() {
        KdTree leaf = new SahBuilder().build(new MeshBuilder().triangle(new double[] {0, 0, 0}, new double[] {1, 0, 0},
                new double[] {0, 1, 0}).build());
        assertThat(leaf.nodeCount()).isEqualTo(1);
        assertThat(SplitsPastLocalMinimum.of(leaf, LAMBDA).cardinality()).isZero();
    }
}
