package org.kdtree.tradeoff;

import java.util.Locale;

/**
 * What one variant costs and buys on one scene and ray workload.
 *
 * @param variant       the variant's name
 * @param settings      the builder's settings, as it describes them
 * @param buildMs       median build time
 * @param expectedCost  the tree's expected SAH cost (lower is better)
 * @param nodes         nodes of the tree
 * @param leaves        leaves of the tree
 * @param memoryBytes   bytes held by the tree's arrays
 * @param nodesPerRay   average nodes visited per ray
 * @param testsPerRay   average ray/triangle tests per ray
 * @param boxesPerRay   average bounding boxes tested per ray (a BVH's; a kd-tree tests none)
 * @param raysPerSecond closest-hit rays traced per second, one thread
 * @param triangles     triangles of the scene, for the totals
 */
public record TradeoffResult(String variant, String settings, double buildMs, double expectedCost, int nodes, int leaves,
                             long memoryBytes, double nodesPerRay, double testsPerRay, double boxesPerRay, double raysPerSecond,
                             int triangles) {

    /**
     * Time to trace {@code raysPerTriangle x triangles} rays, in ms.
     *
     * @param raysPerTriangle rays per triangle of the scene
     * @return the trace time at this result's speed, in ms
     */
    public double traceMs(double raysPerTriangle) {
        return raysPerTriangle * triangles / raysPerSecond * 1e3;
    }

    /**
     * Build plus trace time for {@code raysPerTriangle x triangles} rays, in ms: the time to answer them all.
     *
     * @param raysPerTriangle rays per triangle of the scene
     * @return {@link #buildMs} plus {@link #traceMs}, in ms
     */
    public double totalMs(double raysPerTriangle) {
        return buildMs + traceMs(raysPerTriangle);
    }

    static String csvHeader() {
        return "variant,build_ms,expected_cost,nodes,leaves,memory_bytes,nodes_per_ray,tests_per_ray,boxes_per_ray,mrays_per_s,"
                + "total_ms_1rpt,total_ms_10rpt,total_ms_100rpt,pareto,settings";
    }

    String csvRow(boolean pareto) {
        return String.format(Locale.ROOT, "%s,%.2f,%.3f,%d,%d,%d,%.2f,%.2f,%.2f,%.4f,%.1f,%.1f,%.1f,%s,\"%s\"",
                variant, buildMs, expectedCost, nodes, leaves, memoryBytes, nodesPerRay, testsPerRay,
                boxesPerRay, raysPerSecond / 1e6, totalMs(1), totalMs(10), totalMs(100), pareto, settings);
    }
}
