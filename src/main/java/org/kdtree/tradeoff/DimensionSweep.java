package org.kdtree.tradeoff;

import java.util.List;
import java.util.Locale;
import org.kdtree.generate.Points;
import org.kdtree.kdtree.KdTreeBuilder;
import org.kdtree.points.PointTree;

/**
 * Where kd-trees stop helping: the exact search against brute force on generated points of the
 * same count at growing dimension. In few dimensions the tree scans a handful of leaves; as the
 * dimension grows, a query's ball reaches more and more cells, until the tree scans nearly
 * every leaf and its bookkeeping makes it slower than the plain scan.
 *
 * @param kind       the data: a set of {@link Points#named} (uniform or clustered)
 * @param n          points per dimension measured
 * @param queryCount query points, drawn as the data
 * @param k          neighbours per query
 * @param runs       timed passes per measurement (the median is kept)
 * @param seed       the data's seed (the same for every dimension)
 * @param builder    builds each tree
 */
public record DimensionSweep(String kind, int n, int queryCount, int k, int runs, long seed, KdTreeBuilder builder) {

    /**
     * Builds the tree at {@code dimension} and times its exact search and brute force.
     *
     * @param dimension the points' dimension
     * @return the two speeds and the tree's leaves
     */
    public Result measure(int dimension) {
        PointTree tree = PointTree.build(Points.named(kind, n, dimension, seed), builder);
        NeighbourStudy study = new NeighbourStudy(tree, Points.namedQueries(kind, queryCount, dimension, seed), k, runs);
        NeighbourStudy.Result exact = study.exact();
        return new Result(dimension, exact.queriesPerSecond(), study.bruteQueriesPerSecond(),
                exact.leavesPerQuery(), tree.tree().stats().leaves());
    }

    /**
     * The results as CSV, one row per dimension, in the order given.
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
     * Draws the sweep's chart, titled by its kind of points: the exact search's speed-up over brute
     * force against the dimension, with the break-even line.
     *
     * @param results what {@link #measure} returned, dimension by dimension
     * @param caption the text under the chart ({@link ChartFile#caption})
     * @param file    the chart file, PNG or SVG
     * @throws java.io.IOException if it cannot be written
     */
    public void writeChart(List<Result> results, String caption, java.nio.file.Path file) throws java.io.IOException {
        String title = "Where kd-trees stop helping: exact search against brute force (" + kind.toLowerCase(java.util.Locale.ROOT) + ")";
        ChartFile.write(DimensionChart.chart(results, title), caption, file);
    }

    /**
     * The exact kd-tree search against brute force at one dimension of a sweep.
     *
     * @param dimension      the points' dimension
     * @param exactQps       the exact search's queries per second, one thread
     * @param bruteQps       brute force's queries per second, one thread
     * @param leavesPerQuery leaves the exact search scanned per query on average
     * @param leaves         leaves of the tree
     */
    public record Result(int dimension, double exactQps, double bruteQps, double leavesPerQuery, int leaves) {

        /** {@return how many times faster the tree answers than brute force; below 1 it no longer helps} */
        public double speedUp() {
            return exactQps / bruteQps;
        }

        /** {@return the CSV header matching {@link #csvRow}} */
        public static String csvHeader() {
            return "dimension,exact_queries_per_s,brute_force_queries_per_s,speed_up,leaves_per_query,leaves";
        }

        /** {@return this result as one CSV row, without a line end} */
        public String csvRow() {
            return String.format(Locale.ROOT, "%d,%.1f,%.1f,%.4f,%.2f,%d", dimension, exactQps, bruteQps, speedUp(),
                    leavesPerQuery, leaves);
        }
    }
}
