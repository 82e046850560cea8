package org.kdtree.bench;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.kdtree.generate.Points;
import org.kdtree.kdtree.SlidingMidpointBuilder;
import org.kdtree.points.NearestQuery;
import org.kdtree.points.PointTree;
import org.kdtree.points.RadiusQuery;
import org.kdtree.shape.PointsKd;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;
import org.openjdk.jmh.infra.Blackhole;
import org.tinspin.index.Index;
import org.tinspin.index.kdtree.KDTree;
import smile.neighbor.Neighbor;

/**
 * Point queries against two other Java kd-trees, in the same run: tinspin-indexes' KDTree and
 * Smile's KDTree. For each data set, the build (one operation = one whole tree) and batches of
 * 10,000 queries (one operation = the whole batch): the 10 nearest neighbours, and all points
 * within a radius chosen so that a query finds about 10. Every library answers the same queries
 * (uniform in the unit cube) from the same points ({@link Points}: uniform, or the clustered set
 * of the nearest-neighbour study); {@link #setUp} checks that they agree before anything is timed.
 *
 * <p>tinspin has no radius query: its box query around the ball, filtered by distance, stands
 * in for one (what a user of it would write).
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Warmup(iterations = 3)
@Measurement(iterations = 5)
@Fork(value = 1, jvmArgsAppend = {"-Xmx8g"})
public class PointQueryBenchmark {
    static final int QUERIES = 10_000, K = 10;

    @Param({"uniform-3d-1M", "clustered-3d-1M", "uniform-16d-100K"})
    public String data;

    @Param({"kdtree", "tinspin", "smile"})
    public String library;

    private double[][] points, queries;
    private double radius;
    private PointsKd flat;
    private PointTree ours;
    private NearestQuery nearest;
    private RadiusQuery within;
    private KDTree<Integer> tinspin;
    private smile.neighbor.KDTree<Integer> smile;
    private final int[] idx = new int[4096];
    private final double[] dist = new double[4096];

    @Setup(Level.Trial)
    public void setUp() {
        String[] p = data.split("-");
        int dims = Integer.parseInt(p[1].replace("d", ""));
        int n = Integer.parseInt(p[2].replace("M", "000000").replace("K", "000"));
        flat = p[0].equals("uniform") ? Points.uniform(n, dims, 1) : Points.clustered(n, dims, 2);
        points = rows(flat);
        queries = rows(Points.uniform(QUERIES, dims, 3));
        build();
        radius = radiusForTen();
        checkAgreement();
    }

    @Benchmark
    public Object build() {
        switch (library) {
            case "kdtree" -> {
                ours = PointTree.build(flat, new SlidingMidpointBuilder());
                nearest = new NearestQuery(ours);
                within = new RadiusQuery(ours);
                return ours;
            }
            case "tinspin" -> {
                tinspin = KDTree.create(points[0].length);
                for (int i = 0; i < points.length; i++) tinspin.insert(points[i], i);
                return tinspin;
            }
            default -> {
                Integer[] ids = new Integer[points.length];
                for (int i = 0; i < ids.length; i++) ids[i] = i;
                smile = new smile.neighbor.KDTree<>(points, ids);
                return smile;
            }
        }
    }

    @Benchmark
    public void tenNearest(Blackhole bh) {
        for (double[] q : queries) bh.consume(knn(q));
    }

    @Benchmark
    public void radius(Blackhole bh) {
        for (double[] q : queries) bh.consume(within(q));
    }

    /** The indices of the 10 nearest points, as a sum (order-free, so comparable across libraries). */
    private long knn(double[] q) {
        long sum = 0;
        switch (library) {
            case "kdtree" -> {
                int n = nearest.nearest(q, K, idx, dist);
                for (int i = 0; i < n; i++) sum += idx[i];
            }
            case "tinspin" -> {
                Index.PointIteratorKnn<Integer> it = tinspin.queryKnn(q, K);
                while (it.hasNext()) sum += it.next().value();
            }
            default -> {
                for (Neighbor<double[], Integer> nb : smile.search(q, K)) sum += nb.value;
            }
        }
        return sum;
    }

    /** The number of points within the radius. */
    private int within(double[] q) {
        switch (library) {
            case "kdtree" -> {
                return within.within(q, radius, idx, dist);
            }
            case "tinspin" -> {
                double[] lo = q.clone(), hi = q.clone();
                for (int a = 0; a < q.length; a++) { lo[a] -= radius; hi[a] += radius; }
                int count = 0;
                var it = tinspin.query(lo, hi);
                while (it.hasNext()) if (distance(q, it.next().point()) <= radius) count++;
                return count;
            }
            default -> {
                List<Neighbor<double[], Integer>> out = new ArrayList<>();
                smile.search(q, radius, out);
                return out.size();
            }
        }
    }

    /** A radius holding about 10 points around a query: the median over 100 queries of the 10th distance. */
    private double radiusForTen() {
        PointTree t = ours != null ? ours : PointTree.build(flat, new SlidingMidpointBuilder());
        NearestQuery q = new NearestQuery(t);
        double[] tenth = new double[100];
        for (int i = 0; i < tenth.length; i++) {
            q.nearest(queries[i], K, idx, dist);
            tenth[i] = dist[K - 1];
        }
        java.util.Arrays.sort(tenth);
        return tenth[tenth.length / 2];
    }

    /** All three must give the same answers on the first 200 queries (sums of indices, counts). */
    private void checkAgreement() {
        PointTree t = PointTree.build(flat, new SlidingMidpointBuilder());
        NearestQuery q = new NearestQuery(t);
        RadiusQuery r = new RadiusQuery(t);
        for (int i = 0; i < 200; i++) {
            int n = q.nearest(queries[i], K, idx, dist);
            long expected = 0;
            for (int j = 0; j < n; j++) expected += idx[j];
            int count = r.within(queries[i], radius, idx, dist);
            if (knn(queries[i]) != expected || within(queries[i]) != count)
                throw new IllegalStateException(library + " disagrees with the exact answer on query " + i);
        }
    }

    private static double distance(double[] a, double[] b) {
        double s = 0;
        for (int i = 0; i < a.length; i++) { double d = a[i] - b[i]; s += d * d; }
        return Math.sqrt(s);
    }

    /** The points as one array each, as tinspin and Smile take them. */
    private static double[][] rows(PointsKd p) {
        double[][] rows = new double[p.size()][p.dimension()];
        for (int i = 0; i < rows.length; i++) for (int a = 0; a < rows[i].length; a++) rows[i][a] = p.coord(i, a);
        return rows;
    }
}
