package org.kdtree.points;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.HashSet;
import java.util.List;
import java.util.Set;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.constraints.IntRange;
import org.junit.jupiter.api.Test;
import org.kdtree.points.BruteForcePoints.Neighbour;
import org.kdtree.points.PointSets.Kind;
import org.kdtree.shape.PointsKd;
import org.kdtree.spec.Builders;

/** Best-bin-first with a budget of leaves, and the (1 + eps) bound. */
class ApproximateSearchTest {
    @Property(tries = 25)
    void anUnlimitedBudgetIsExact(@ForAll Kind kind, @ForAll @IntRange(min = 0, max = 3) int dim, @ForAll long seed) {
        PointsKd pts = PointSets.of(kind, 300, PointSets.DIMENSIONS[dim], seed);
        PointTree tree = PointTree.build(pts, Builders.create("sliding-midpoint"));
        // a budget of every leaf runs best-bin-first to its natural end
        NearestQuery bbf = new NearestQuery(tree).maxLeaves(tree.tree().stats().leaves());
        int[] idx = new int[10];
        double[] dist = new double[10];
        for (double[] q : PointSets.queries(pts, 12, seed)) {
            int n = bbf.nearest(q, 10, idx, dist);
            assertThat(BruteForcePoints.of(n, idx, dist)).as(kind + " " + q.length + "-D")
                    .isEqualTo(BruteForcePoints.nearest(pts, q, 10, 2, Double.POSITIVE_INFINITY));
        }
    }

    @Property(tries = 25)
    void aBudgetGivesValidResults(@ForAll Kind kind, @ForAll @IntRange(min = 0, max = 3) int dim,
                                  @ForAll @IntRange(min = 1, max = 5) int leaves, @ForAll long seed) {
        PointsKd pts = PointSets.of(kind, 400, PointSets.DIMENSIONS[dim], seed);
        PointTree tree = PointTree.build(pts, Builders.create("sliding-midpoint"));
        NearestQuery bbf = new NearestQuery(tree).maxLeaves(leaves);
        int[] idx = new int[10];
        double[] dist = new double[10];
        for (double[] q : PointSets.queries(pts, 12, seed)) {
            int n = bbf.nearest(q, 10, idx, dist);
            assertThat(bbf.leavesVisited()).isLessThanOrEqualTo(leaves);
            assertThat(n).as("the first leaf alone holds at least one point").isBetween(1, 10);
            Set<Integer> distinct = new HashSet<>();
            for (int i = 0; i < n; i++) {
                assertThat(idx[i]).isBetween(0, pts.size() - 1);
                assertThat(distinct.add(idx[i])).as("point " + idx[i] + " listed twice").isTrue();
                assertThat(dist[i]).as("reported distance of point " + idx[i])
                        .isEqualTo(BruteForcePoints.root(BruteForcePoints.accumulated(pts, idx[i], q, 2), 2));
                if (i > 0) assertThat(dist[i]).as("sorted").isGreaterThanOrEqualTo(dist[i - 1]);
            }
        }
    }

    @Test void recallOnEasyDataIsHighWithAFewLeaves() {
        PointsKd pts = PointSets.of(Kind.UNIFORM, 5000, 3, 11);
        PointTree tree = PointTree.build(pts, Builders.create("sliding-midpoint"));
        NearestQuery bbf = new NearestQuery(tree).maxLeaves(8);
        int[] idx = new int[10];
        int found = 0, wanted = 0;
        java.util.Random r = new java.util.Random(3);
        for (int j = 0; j < 200; j++) {
            double[] q = {r.nextDouble(), r.nextDouble(), r.nextDouble()};
            int n = bbf.nearest(q, 10, idx, null);
            Set<Integer> truth = new HashSet<>();
            for (Neighbour nb : BruteForcePoints.nearest(pts, q, 10, 2, Double.POSITIVE_INFINITY)) truth.add(nb.index());
            for (int i = 0; i < n; i++) if (truth.contains(idx[i])) found++;
            wanted += truth.size();
        }
        double recall = (double) found / wanted;
        assertThat(recall).as("recall of 10-NN scanning 8 of ~%d leaves", tree.tree().stats().leaves()).isGreaterThanOrEqualTo(0.9);
    }

    @Property(tries = 25)
    void epsilonKeepsEachNeighbourWithinItsFactor(@ForAll Kind kind, @ForAll @IntRange(min = 0, max = 3) int dim,
                                                  @ForAll @IntRange(min = 0, max = 3) int e, @ForAll long seed) {
        double eps = new double[] {0.1, 0.5, 1, 3}[e];
        PointsKd pts = PointSets.of(kind, 400, PointSets.DIMENSIONS[dim], seed);
        PointTree tree = PointTree.build(pts, Builders.create("sliding-midpoint"));
        NearestQuery approx = new NearestQuery(tree).epsilon(eps);
        int[] idx = new int[8];
        double[] dist = new double[8];
        for (double[] q : PointSets.queries(pts, 12, seed)) {
            int n = approx.nearest(q, 8, idx, dist);
            List<Neighbour> truth = BruteForcePoints.nearest(pts, q, 8, 2, Double.POSITIVE_INFINITY);
            assertThat(n).isEqualTo(truth.size());
            for (int i = 0; i < n; i++)
                assertThat(dist[i]).as("rank %d with eps %s", i, eps).isLessThanOrEqualTo((1 + eps) * truth.get(i).distance() * (1 + 1e-9));
        }
    }
}
