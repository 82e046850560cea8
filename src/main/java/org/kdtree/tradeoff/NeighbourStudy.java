package org.kdtree.tradeoff;

import java.util.List;
import java.util.Locale;
import org.kdtree.measure.Timing;
import org.kdtree.points.NearestQuery;
import org.kdtree.points.PointTree;
import org.kdtree.shape.PointsKd;

/**
 * "What accuracy costs" for nearest neighbours: on one point tree and one query set, how much
 * of the true answer an approximate search finds (recall at k) and how many queries per second
 * it answers, against the exact search and against scanning every point. Euclidean, one thread.
 *
 * <p>The exact answers (the oracle) come from {@link BruteForceNeighbours}, computed once when
 * the study is made; that pass also warms brute force up. Every timed measurement is the median
 * of {@code runs} passes over all the queries, after an untimed pass that warms the code up and
 * measures the recall.
 */
public final class NeighbourStudy {
    private final PointTree tree;
    private final double[][] queries;
    private final int k;
    private final int kk;
    private final int runs;
    private final BruteForceNeighbours brute;
    private final double[] kth;
    private double bruteQps = Double.NaN;
    /** Keeps the timed loops' answers alive, so that the JIT cannot drop them. */
    private volatile long sink;

    /**
     * @param tree    the points and their tree
     * @param queries query points of the tree's dimension
     * @param k       neighbours per query (>= 1; min(k, points) are asked)
     * @param runs    timed passes per measurement (>= 1), of which the median is kept
     */
    public NeighbourStudy(PointTree tree, PointsKd queries, int k, int runs) {
        if (queries.dimension() != tree.dimension())
            throw new IllegalArgumentException("the queries are " + queries.dimension() + "-D, the points " + tree.dimension() + "-D");
        if (queries.size() == 0) throw new IllegalArgumentException("no query points");
        if (k < 1 || runs < 1) throw new IllegalArgumentException("k and runs must be >= 1, got " + k + " and " + runs);
        this.tree = tree;
        this.queries = rows(queries);
        this.k = k;
        this.kk = Math.min(k, tree.size());
        this.runs = runs;
        this.brute = new BruteForceNeighbours(tree.points());
        this.kth = new double[this.queries.length];
        for (int j = 0; j < kth.length; j++) kth[j] = brute.kthSquaredDistance(this.queries[j], k);
    }

    /** {@return the queries answered by scanning every point: the baseline (recall 1, speed-up 1)} */
    public Result bruteForce() {
        return new Result(NeighbourSearch.BRUTE_FORCE, "", 1, bruteQueriesPerSecond(), 0, 1);
    }

    /** {@return the kd-tree's exact search, measured} */
    public Result exact() {
        return measure(NeighbourSearch.EXACT, "", new NearestQuery(tree));
    }

    /**
     * Best-bin-first, stopping after {@code maxLeaves} leaves ({@link NearestQuery#UNLIMITED}: exact).
     *
     * @param maxLeaves the budget of leaves per query, >= 1
     * @return the search's recall and speed
     */
    public Result budget(int maxLeaves) {
        String setting = maxLeaves == NearestQuery.UNLIMITED ? "unlimited" : Integer.toString(maxLeaves);
        return measure(NeighbourSearch.BEST_BIN_FIRST, setting, new NearestQuery(tree).maxLeaves(maxLeaves));
    }

    /**
     * The search with the {@code (1 + eps)} bound.
     *
     * @param eps the allowed relative error, finite and >= 0
     * @return the search's recall and speed
     */
    public Result epsilon(double eps) {
        return measure(NeighbourSearch.EPSILON, org.kdtree.limits.Limit.format(eps), new NearestQuery(tree).epsilon(eps));
    }

    /** {@return brute force's queries per second, measured on first use} */
    public double bruteQueriesPerSecond() {
        if (Double.isNaN(bruteQps)) bruteQps = queries.length / medianSeconds(this::bruteForcePass);
        return bruteQps;
    }

    /** {@return the number of query points} */
    public int queryCount() {
        return queries.length;
    }

    private Result measure(NeighbourSearch search, String setting, NearestQuery knn) {
        int[] found = new int[kk];
        double recall = 0;
        long leaves = 0;
        for (int j = 0; j < queries.length; j++) {
            int m = knn.nearest(queries[j], k, found, null);
            recall += correct(j, found, m) / (double) kk;
            leaves += knn.leavesVisited();
        }
        double qps = queries.length / medianSeconds(() -> treePass(knn, found));
        return new Result(search, setting, recall / queries.length, qps, leaves / (double) queries.length,
                qps / bruteQueriesPerSecond());
    }

    /** How many of the {@code m} points found for query {@code j} are at most as far as its true k-th neighbour. */
    private int correct(int j, int[] found, int m) {
        int c = 0;
        for (int i = 0; i < m; i++) if (brute.squaredDistance(queries[j], found[i], Double.POSITIVE_INFINITY) <= kth[j]) c++;
        return c;
    }

    private void treePass(NearestQuery knn, int[] found) {
        long s = 0;
        for (double[] q : queries) s += knn.nearest(q, k, found, null) + found[0];
        sink += s;
    }

    private void bruteForcePass() {
        double s = 0;
        for (double[] q : queries) s += brute.kthSquaredDistance(q, k);
        sink += (long) s;
    }

    /** The median time of {@code runs} passes, in seconds (at least a nanosecond). */
    private double medianSeconds(Runnable pass) {
        return Timing.medianSeconds(0, runs, pass);
    }

    private static double[][] rows(PointsKd points) {
        double[][] r = new double[points.size()][points.dimension()];
        for (int i = 0; i < r.length; i++) for (int a = 0; a < r[i].length; a++) r[i][a] = points.coord(i, a);
        return r;
    }

    /**
     * The results as CSV, one row each, in the order given.
     *
     * @param results the measurements
     * @return the header and one line per result
     */
    public static String csv(List<Result> results) {
        StringBuilder sb = new StringBuilder(Result.csvHeader()).append('\n');
        for (Result r : results) sb.append(r.csvRow()).append('\n');
        return sb.toString();
    }

    /**
     * Draws the study's accuracy chart: recall at k against queries per second, one line per
     * approximate search, the exact search and brute force as reference lines.
     *
     * @param results the measurements
     * @param title   the chart's title
     * @param caption the text under the chart ({@link ChartFile#caption})
     * @param file    the chart file, PNG or SVG
     * @throws java.io.IOException if it cannot be written
     */
    public static void writeChart(List<Result> results, String title, String caption, java.nio.file.Path file) throws java.io.IOException {
        ChartFile.write(NeighbourChart.chart(results, title), caption, file);
    }

    /**
     * What one way of answering the queries of a nearest-neighbour study buys and costs.
     *
     * @param search           how the queries were answered
     * @param setting          the budget or epsilon ("16", "0.5"), or "" for brute force and the exact search
     * @param recall           the mean over the queries of the fraction of the true k nearest found
     *                         (a point as near as the true k-th counts), in [0, 1]
     * @param queriesPerSecond queries answered per second, one thread (median of the timed runs)
     * @param leavesPerQuery   leaves scanned per query on average (0 for brute force)
     * @param speedUp          queries per second over those of brute force
     */
    public record Result(NeighbourSearch search, String setting, double recall, double queriesPerSecond,
                                  double leavesPerQuery, double speedUp) {

        /** {@return the CSV header matching {@link #csvRow}} */
        public static String csvHeader() {
            return "search,setting,recall,queries_per_s,leaves_per_query,speed_up";
        }

        /** {@return this result as one CSV row, without a line end} */
        public String csvRow() {
            return String.format(Locale.ROOT, "%s,%s,%.6f,%.1f,%.2f,%.4f", search.label(), setting, recall,
                    queriesPerSecond, leavesPerQuery, speedUp);
        }

        /** {@return the name of this row in a table: the search and its setting} */
        public String name() {
            return setting.isEmpty() ? search.label() : search.label() + " " + setting;
        }
    }
}
