package org.kdtree.tradeoff;

import java.util.List;
import org.kdtree.kdtree.KdTreeBuilder;
import org.kdtree.points.PointTree;

/**
 * Where kd-trees stop helping: the exact search against brute force on generated points of the
 * same count at growing dimension. In few dimensions the tree scans a handful of leaves; as the
 * dimension grows, a query's ball reaches more and more cells, until the tree scans nearly
 * every leaf and its bookkeeping makes it slower than the plain scan.
 *
 * @param kind       the data
 * @param n          points per dimension measured
 * @param queryCount query points, drawn as the data
 * @param k          neighbours per query
 * @param runs       timed passes per measurement (the median is kept)
 * @param seed       the data's seed (the same for every dimension)
 * @param builder    builds each tree
 */
public record DimensionSweep(GeneratedPoints kind, int n, int queryCount, int k, int runs, long seed, KdTreeBuilder builder) {

    /**
     * Builds the tree at {@code dimension} and times its exact search and brute force.
     *
     * @param dimension the points' dimension
     * @return the two speeds and the tree's leaves
     */
    public DimensionResult measure(int dimension) {
        PointTree tree = PointTree.build(kind.points(n, dimension, seed), builder);
        NeighbourStudy study = new NeighbourStudy(tree, kind.queries(queryCount, dimension, seed), k, runs);
        NeighbourResult exact = study.exact();
        return new DimensionResult(dimension, exact.queriesPerSecond(), study.bruteQueriesPerSecond(),
                exact.leavesPerQuery(), tree.tree().stats().leaves());
    }

    /**
     * The results as CSV, one row per dimension, in the order given.
     *
     * @param results the measurements
     * @return the header and one line per result
     */
    public static String csv(List<DimensionResult> results) {
        StringBuilder sb = new StringBuilder(DimensionResult.csvHeader()).append('\n');
        for (DimensionResult r : results) sb.append(r.csvRow()).append('\n');
        return sb.toString();
    }
}
