package org.kdtree.points;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.constraints.IntRange;
import org.junit.jupiter.api.Test;
import org.kdtree.points.BruteForcePoints.Neighbour;
import org.kdtree.points.PointSets.Kind;
import org.kdtree.shape.PointsKd;
import org.kdtree.spec.Builders;

/**
 * k-NN (with and without a maximum distance), radius and box queries against brute force over
 * all points, on every kind of data, in 2, 3, 8, 32 and 64 dimensions, on the trees of every
 * registered builder: the same points, in the same order, at the same distances.
 */
class ExactQueriesTest {
    private static final List<String> BUILDERS = new ArrayList<>(Builders.names());

    /** Every kind, dimension and builder once. */
    @Test void everyKindDimensionAndBuilder() {
        for (Kind kind : Kind.values())
            for (int k : PointSets.DIMENSIONS)
                for (String builder : BUILDERS)
                    checkAll(kind, k, builder, 250, 7 + k, 2);
    }

    @Property(tries = 40)
    void anyPointSet(@ForAll Kind kind, @ForAll @IntRange(min = 0, max = 3) int dim, @ForAll @IntRange(min = 0, max = 99) int builder,
                     @ForAll @IntRange(min = 0, max = 300) int n, @ForAll long seed) {
        checkAll(kind, PointSets.DIMENSIONS[dim], BUILDERS.get(builder % BUILDERS.size()), n, seed, 2);
    }

    @Property(tries = 20)
    void otherMetrics(@ForAll Kind kind, @ForAll @IntRange(min = 0, max = 2) int dim, @ForAll @IntRange(min = 0, max = 2) int metric,
                      @ForAll long seed) {
        double p = new double[] {1, 3.5, Double.POSITIVE_INFINITY}[metric];
        checkAll(kind, PointSets.DIMENSIONS[dim], "sliding-midpoint", 200, seed, p);
    }

    @Test void emptyAndSinglePointSets() {
        for (int n : new int[] {0, 1}) {
            PointTree tree = PointTree.build(PointSets.of(Kind.UNIFORM, n, 3, 1), Builders.create("sliding-midpoint"));
            int[] idx = new int[4];
            double[] dist = new double[4];
            assertThat(new NearestQuery(tree).nearest(new double[] {5, 5, 5}, 4, idx, dist)).isEqualTo(n);
            assertThat(new RadiusQuery(tree).within(new double[] {5, 5, 5}, 100, idx, dist)).isEqualTo(n);
            assertThat(new BoxQuery(tree).inside(new double[] {-9, -9, -9}, new double[] {9, 9, 9}, idx)).isEqualTo(n);
        }
    }

    @Test void radiusQueryReportsTheFullCountWhenTheArraysAreShort() {
        PointsKd pts = PointSets.of(Kind.GRID, 500, 2, 3);
        PointTree tree = PointTree.build(pts, Builders.create("sliding-midpoint"));
        double[] q = {1.5, 1.5};
        List<Neighbour> all = BruteForcePoints.sorted(pts, q, 2, 1.0);
        int[] idx = new int[5];
        double[] dist = new double[5];
        int count = new RadiusQuery(tree).within(q, 1.0, idx, dist);
        assertThat(count).as("points within 1 of a grid cell's centre").isEqualTo(all.size()).isGreaterThan(5);
        assertThat(BruteForcePoints.of(5, idx, dist)).isEqualTo(all.subList(0, 5));
    }

    /** k-NN, k-NN within a radius, radius and box queries for a batch of queries, all against the oracle. */
    private static void checkAll(Kind kind, int k, String builder, int n, long seed, double p) {
        PointsKd pts = PointSets.of(kind, n, k, seed);
        PointTree tree = PointTree.build(pts, Builders.create(builder));
        Metric metric = Metric.minkowski(p);
        NearestQuery knn = new NearestQuery(tree).metric(metric);
        RadiusQuery ball = new RadiusQuery(tree).metric(metric);
        BoxQuery box = new BoxQuery(tree);
        Random r = new Random(seed);
        int[] idx = new int[Math.max(1, n)];
        double[] dist = new double[Math.max(1, n)];
        String where = kind + " " + k + "-D n=" + n + " " + builder + " p=" + p + " seed=" + seed;
        for (double[] q : PointSets.queries(pts, 12, seed)) {
            int kk = 1 + r.nextInt(12);
            int got = knn.nearest(q, kk, idx, dist);
            assertThat(BruteForcePoints.of(got, idx, dist)).as("k-NN, k=" + kk + ", " + where)
                    .isEqualTo(BruteForcePoints.nearest(pts, q, kk, p, Double.POSITIVE_INFINITY));
            double radius = radiusFor(pts, q, p, r);
            got = knn.nearest(q, kk, radius, idx, dist);
            assertThat(BruteForcePoints.of(got, idx, dist)).as("k-NN within " + radius + ", k=" + kk + ", " + where)
                    .isEqualTo(BruteForcePoints.nearest(pts, q, kk, p, radius));
            got = ball.within(q, radius, idx, dist);
            assertThat(BruteForcePoints.of(got, idx, dist)).as("within " + radius + ", " + where)
                    .isEqualTo(BruteForcePoints.sorted(pts, q, p, radius));
            double[] lo = new double[k], hi = new double[k];
            for (int a = 0; a < k; a++) {
                double half = r.nextDouble() * (kind == Kind.GRID ? 2 : 0.6);
                lo[a] = q[a] - half;
                hi[a] = q[a] + half;
            }
            got = box.inside(lo, hi, idx);
            List<Integer> gotBox = new ArrayList<>();
            for (int i = 0; i < got; i++) gotBox.add(idx[i]);
            assertThat(gotBox).as("box query, " + where).isEqualTo(BruteForcePoints.inside(pts, lo, hi));
        }
    }

    /** A radius that is exactly some point's distance (a tie at the boundary) half the time, else random. */
    private static double radiusFor(PointsKd pts, double[] q, double p, Random r) {
        if (pts.size() == 0) return r.nextDouble();
        List<Neighbour> s = BruteForcePoints.sorted(pts, q, p, Double.POSITIVE_INFINITY);
        Neighbour pick = s.get(r.nextInt(Math.min(s.size(), 20)));
        return r.nextBoolean() ? pick.distance() : pick.distance() * r.nextDouble();
    }
}
