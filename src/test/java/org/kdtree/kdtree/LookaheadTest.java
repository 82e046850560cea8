package org.kdtree.kdtree;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.Random;
import org.junit.jupiter.api.Test;
import org.kdtree.accel.TriangleIntersector;
import org.kdtree.generate.Meshes;
import org.kdtree.geom.Box;
import org.kdtree.geom.Ray;
import org.kdtree.shape.TriangleMesh;

/**
 * The talk's "a few more iterations" ({@link SahBuilder#lookahead}): the cost criterion can stop
 * at a local minimum, so up to N splits that do not beat the leaf are still made along a path,
 * and each subtree is kept only where it ends cheaper than the leaf it replaced.
 */
class LookaheadTest {
    /**
     * Two small triangles in opposite corners of a 1 x 1 x 0.5 box: any plane through the root
     * leaves one triangle on each side, in a child of two thirds or more of the root's area or so,
     * which costs more than the leaf of two (so the default tree is that leaf, cost 2 Ki); but
     * each child, once made, carves its triangle out of empty space, and the whole subtree ends
     * cheaper than the leaf. A lookahead of 1 finds it.
     */
    static TriangleMesh twoCorners() {
        double e = 0.01, h = 0.5;
        return new MeshBuilder().triangle(new double[] {0, 0, 0}, new double[] {e, 0, 0}, new double[] {0, e, e})
                .triangle(new double[] {1, 1, h}, new double[] {1 - e, 1, h}, new double[] {1, 1 - e, h - e}).build();
    }

    @Test void aSplitThatDoesNotPayAloneIsMadeWhenTheSubtreeBelowItDoes() {
        TriangleMesh scene = twoCorners();
        KdTree stop = new SahBuilder().build(scene), onePast = new SahBuilder().lookahead(1).build(scene);
        double ki = stop.costModel().ki();
        assertThat(stop.nodeCount()).as("the default tree: one leaf").isEqualTo(1);
        assertThat(stop.stats().expectedCost()).isEqualTo(2 * ki);
        assertThat(onePast.nodeCount()).as("lookahead 1: a subtree").isGreaterThan(1);
        assertThat(onePast.stats().expectedCost()).as("lookahead 1's expected cost").isLessThan(stop.stats().expectedCost() - 1);
        assertThat(new SahBuilder().lookahead(2).build(scene).stats().expectedCost())
                .isLessThanOrEqualTo(onePast.stats().expectedCost());
        checkRays(scene, onePast, 500);
    }

    /**
     * Where the subtree past the criterion does not end cheaper, it is thrown away: a lookahead
     * never raises the expected cost, and on generated scenes it lowers it a little, with more nodes.
     */
    @Test void moreLookaheadNeverCostsMoreAndFindsCheaperTrees() {
        for (TriangleMesh scene : new TriangleMesh[] {Meshes.clustered(3000, 0.02, 41), Meshes.surface(30, 40, 42)}) {
            KdTree previous = new SahBuilder().build(scene), none = previous;
            for (int n = 1; n <= 3; n++) {
                KdTree tree = new SahBuilder().lookahead(n).build(scene);
                double cost = tree.stats().expectedCost(), before = previous.stats().expectedCost();
                assertThat(cost).as("lookahead %d against %d", n, n - 1).isLessThanOrEqualTo(before * (1 + 1e-12));
                previous = tree;
            }
            assertThat(previous.stats().expectedCost()).as("lookahead 3 against 0").isLessThan(none.stats().expectedCost());
            assertThat(previous.nodeCount()).isGreaterThan(none.nodeCount());
        }
    }

    @Test void lookaheadTreesAnswerRaysAsBruteForceDoes() {
        TriangleMesh scene = Meshes.clustered(2000, 0.03, 43);
        for (int n = 1; n <= 3; n++) checkRays(scene, new SahBuilder().lookahead(n).build(scene), 1500);
        checkRays(scene, new SahBuilder().lookahead(2).perfectSplits(false).build(scene), 1500);
    }

    @Test void twoThreadsBuildTheTreeOfOne() {
        TriangleMesh scene = Meshes.clustered(6000, 0.02, 44);
        KdTree one = new SahBuilder().lookahead(2).build(scene);
        SahAlgorithmsTest.assertSameTree(new SahBuilder().lookahead(2).threads(2).build(scene), one);
    }

    /**
     * 5,000 big triangles, corners anywhere in the unit cube: every plane cuts most of them, so
     * the default tree stops at leaves of thousands of references; a split of such a leaf on trial
     * has children big enough (2,048 references and more) for the right one to be built on another
     * thread and spliced in, and the trial's outcome, kept or taken back after the splice, is the
     * sequential build's.
     */
    @Test void aTrialSplitWhoseSubtreeIsBuiltOnTwoThreads() {
        MeshBuilder m = new MeshBuilder();
        Random r = new Random(47);
        for (int i = 0; i < 5000; i++)
            m.triangle(new double[] {r.nextDouble(), r.nextDouble(), r.nextDouble()},
                    new double[] {r.nextDouble(), r.nextDouble(), r.nextDouble()},
                    new double[] {r.nextDouble(), r.nextDouble(), r.nextDouble()});
        TriangleMesh scene = m.build();
        KdTree none = new SahBuilder().build(scene);
        int[] largest = {0};
        none.walk(new TreeVisitor() {
            @Override public void interior(int node, int depth, Box voxel, int axis, double split) { }
            @Override public void leaf(int node, int depth, Box voxel, int from, int to) { largest[0] = Math.max(largest[0], to - from); }
        });
        assertThat(largest[0]).as("the default tree's largest leaf").isGreaterThanOrEqualTo(2 * 2048);
        for (int n = 1; n <= 3; n++) {
            KdTree one = new SahBuilder().lookahead(n).build(scene);
            SahAlgorithmsTest.assertSameTree(new SahBuilder().lookahead(n).threads(2).build(scene), one, "lookahead " + n);
            BuildWatch watch = BuildWatch.watched();
            new SahBuilder().lookahead(n).threads(2).build(scene, watch);
            assertThat(watch.nodes()).as("lookahead %d: nodes built, some of them taken back", n).isGreaterThan(one.nodeCount());
            assertThat(one.stats().expectedCost()).isLessThanOrEqualTo(none.stats().expectedCost() * (1 + 1e-12));
            checkRays(scene, one, 300);
        }
    }

    /** A trial split is a split like any other: the depth cap and the reference budget still bind. */
    @Test void theDepthCapAndTheReferenceBudgetStillBind() {
        TriangleMesh scene = Meshes.clustered(3000, 0.02, 45);
        KdTree capped = new SahBuilder().lookahead(3).maxDepth(9).build(scene);
        assertThat(capped.stats().maxDepth()).isEqualTo(9);
        KdTree tight = new SahBuilder().lookahead(3).referenceBudget(2).build(scene);
        assertThat((long) tight.refArray().length).isLessThanOrEqualTo(2L * scene.size());
        assertThat(tight.budgetLeaves()).isPositive();
        checkRays(scene, capped, 500);
        checkRays(scene, tight, 500);
    }

    @Test void zeroIsTheDefaultAndTheRangeIsChecked() {
        TriangleMesh scene = Meshes.clustered(1000, 0.02, 46);
        assertThat(new SahBuilder().lookahead()).isZero();
        SahAlgorithmsTest.assertSameTree(new SahBuilder().lookahead(0).build(scene), new SahBuilder().build(scene));
        assertThat(new SahBuilder().lookahead(2).describeSettings()).contains("lookahead=2");
        assertThatThrownBy(() -> new SahBuilder().lookahead(9)).isInstanceOf(IllegalArgumentException.class)
                .hasMessageStartingWith("lookahead must be between 0 and 8");
        assertThatThrownBy(() -> new SahBuilder().lookahead(-1)).isInstanceOf(IllegalArgumentException.class);
    }

    /**
     * Rays from around the scene's box, half towards a random point of a random triangle (so that
     * small scenes are hit too), half towards a random point of the box; each checked against brute force.
     */
    private static void checkRays(TriangleMesh scene, KdTree tree, int count) {
        Oracle oracle = new Oracle(new TriangleIntersector(scene), tree, "sah " + tree.nodeCount() + " nodes");
        Box box = KdTreeBuilder.rootVoxel(scene);
        Random r = new Random(count);
        int hits = 0;
        for (int i = 0; i < count; i++) {
            int t = r.nextInt(scene.size());
            double u = r.nextDouble(), v = r.nextDouble() * (1 - u);
            double[] o = new double[3], d = new double[3];
            for (int a = 0; a < 3; a++) {
                double lo = box.min(a), w = box.max(a) - lo;
                o[a] = lo - w + 3 * w * r.nextDouble();
                double target = i % 2 == 0 ? lo + w * r.nextDouble()
                        : (1 - u - v) * scene.corner(t, 0, a) + u * scene.corner(t, 1, a) + v * scene.corner(t, 2, a);
                d[a] = target - o[a];
            }
            if (oracle.check(new Ray(o, d))) hits++;
        }
        assertThat(hits).as("rays that hit").isGreaterThan(count / 4);
    }
}
