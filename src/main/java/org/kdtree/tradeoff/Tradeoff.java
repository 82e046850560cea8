package org.kdtree.tradeoff;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.kdtree.accel.AccelerationStructure;
import org.kdtree.accel.SharedSettings;
import org.kdtree.accel.TraversalStats;
import org.kdtree.accel.TreeStats;
import org.kdtree.kdtree.Supervisor;
import org.kdtree.measure.RayBatch;
import org.kdtree.measure.RaySet;
import org.kdtree.measure.Timing;
import org.kdtree.shape.TriangleMesh;
import org.kdtree.spec.BuilderSpec;

/**
 * "What accuracy costs in time": builds the scene with each variant (a kd-tree or a bounding
 * volume hierarchy), then traces the ray workload, and reports build time, tree quality
 * (expected SAH cost) and trace speed side by side.
 */
public final class Tradeoff {
    private final TriangleMesh mesh;
    private final RaySet rays;
    private final int runs;
    private final int threads;
    private final int countedRays;
    private final Supervisor supervisor;

    /**
     * @param mesh        the scene every variant builds its tree over
     * @param rays        the ray workload traced with each tree
     * @param runs        timed builds and traces per variant (the median is kept), after one warm-up
     * @param threads     threads for the builds (tracing is single-threaded)
     * @param countedRays rays traced once more with a listener to count nodes and tests per ray
     */
    public Tradeoff(TriangleMesh mesh, RaySet rays, int runs, int threads, int countedRays) {
        this(mesh, rays, runs, threads, countedRays, null);
    }

    private Tradeoff(TriangleMesh mesh, RaySet rays, int runs, int threads, int countedRays, Supervisor supervisor) {
        this.supervisor = supervisor;
        this.mesh = mesh;
        this.rays = rays;
        this.runs = Math.max(1, runs);
        this.threads = threads;
        this.countedRays = Math.max(1, countedRays);
    }

    /**
     * {@return the same study with each build run by {@code s}} (a registered plug-in builder is
     * a variant too: it may throw, hang or be slow, and is then stopped and named)
     *
     * @param s the supervisor of the builds
     */
    public Tradeoff supervisedBy(Supervisor s) {
        return new Tradeoff(mesh, rays, runs, threads, countedRays, s);
    }

    /**
     * Measures one variant, a kd-tree's or a bounding volume hierarchy's, by the same rays and counts.
     *
     * @param v the variant
     * @return its build time, tree quality and trace speed
     */
    public Result run(Variant v) {
        BuilderSpec spec = v.spec().with(SharedSettings.THREADS, threads);
        String settings = spec.describe();
        Timing.Timed<AccelerationStructure> build = Timing.median(1, runs, Timing.QUIET, () -> spec.build(mesh, supervisor));
        AccelerationStructure structure = build.value();
        TreeStats s = structure.stats();
        double traceSeconds;
        String engine;
        try (RayBatch batch = new RayBatch(1, structure)) {
            traceSeconds = Timing.median(1, runs, Timing.QUIET, () -> batch.trace(rays)).seconds();
            // one CSV field without a comma: the study's readers (and a spreadsheet's quick import) split on every comma
            engine = (structure.kind() + "; " + batch.loopOf(rays) + "; " + structure.describePath()).replace(',', ';');
        }
        TraversalStats counts = RayBatch.count(structure, rays, countedRays);
        double perRay = Math.max(1, counts.rays);
        return new Result(v.name(), settings, build.millis(), s.expectedCost(), s.nodes(),
                s.leaves(), s.memoryBytes(), counts.nodes / perRay, counts.primitiveTests / perRay, counts.boxTests / perRay,
                rays.size() / traceSeconds, mesh.size(), engine);
    }

    /**
     * The Pareto front of build time against trace time: results no other result beats on both
     * (at least as fast to build and to trace, and faster on one).
     *
     * @param results the measurements
     * @return for each result, in order, whether it is on the front
     */
    public static boolean[] paretoFront(List<Result> results) {
        boolean[] front = new boolean[results.size()];
        for (int i = 0; i < front.length; i++) {
            Result a = results.get(i);
            front[i] = results.stream().noneMatch(b -> b != a && b.buildMs() <= a.buildMs()
                    && b.raysPerSecond() >= a.raysPerSecond()
                    && (b.buildMs() < a.buildMs() || b.raysPerSecond() > a.raysPerSecond()));
        }
        return front;
    }

    /**
     * The results as CSV, with a Pareto column.
     *
     * @param results the measurements
     * @return the header and one line per result, in order
     */
    public static String csv(List<Result> results) {
        boolean[] front = paretoFront(results);
        StringBuilder sb = new StringBuilder(Result.csvHeader()).append('\n');
        for (int i = 0; i < results.size(); i++) sb.append(results.get(i).csvRow(front[i])).append('\n');
        return sb.toString();
    }

    /**
     * Draws the study's chart: build time against trace time for a workload, one point per
     * variant, the Pareto front marked.
     *
     * @param results         the measurements, one point per variant
     * @param title           the chart's title
     * @param raysPerTriangle the workload: rays traced per triangle of the scene
     * @param caption         the text under the chart ({@link ChartFile#caption})
     * @param file            the chart file, PNG or SVG
     * @throws java.io.IOException if it cannot be written
     */
    public static void writeChart(List<Result> results, String title, double raysPerTriangle, String caption, java.nio.file.Path file)
            throws java.io.IOException {
        TradeoffChart.write(results, title, raysPerTriangle, caption, file);
    }

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
     * @param engine        which structure, which loop and which path traced the rays
     */
    public record Result(String variant, String settings, double buildMs, double expectedCost, int nodes, int leaves,
                                 long memoryBytes, double nodesPerRay, double testsPerRay, double boxesPerRay, double raysPerSecond,
                                 int triangles, String engine) {

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
                    + "total_ms_1rpt,total_ms_10rpt,total_ms_100rpt,pareto,settings,engine";
        }

        String csvRow(boolean pareto) {
            return String.format(Locale.ROOT, "%s,%.2f,%.3f,%d,%d,%d,%.2f,%.2f,%.2f,%.4f,%.1f,%.1f,%.1f,%s,\"%s\",\"%s\"",
                    variant, buildMs, expectedCost, nodes, leaves, memoryBytes, nodesPerRay, testsPerRay,
                    boxesPerRay, raysPerSecond / 1e6, totalMs(1), totalMs(10), totalMs(100), pareto, settings, engine);
        }
    }
}
