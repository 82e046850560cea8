package org.kdtree.tradeoff;

import java.util.Locale;

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
public record NeighbourResult(NeighbourSearch search, String setting, double recall, double queriesPerSecond,
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
