package org.kdtree.tradeoff;

import java.util.Locale;

/**
 * The exact kd-tree search against brute force at one dimension of a sweep.
 *
 * @param dimension      the points' dimension
 * @param exactQps       the exact search's queries per second, one thread
 * @param bruteQps       brute force's queries per second, one thread
 * @param leavesPerQuery leaves the exact search scanned per query on average
 * @param leaves         leaves of the tree
 */
public record DimensionResult(int dimension, double exactQps, double bruteQps, double leavesPerQuery, int leaves) {

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
