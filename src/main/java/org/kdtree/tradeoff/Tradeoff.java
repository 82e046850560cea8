package org.kdtree.tradeoff;

import java.util.ArrayList;
import java.util.List;
import org.kdtree.accel.AccelerationStructure;
import org.kdtree.accel.RayQuery;
import org.kdtree.accel.SharedSettings;
import org.kdtree.accel.TraversalStats;
import org.kdtree.accel.TreeStats;
import org.kdtree.accel.TriangleIntersector;
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
    public TradeoffResult run(Variant v) {
        BuilderSpec spec = v.spec().with(SharedSettings.THREADS, threads);
        String settings = spec.describe();
        Timing.Timed<AccelerationStructure> build = Timing.median(1, runs, Timing.QUIET, () -> spec.build(mesh, supervisor));
        AccelerationStructure structure = build.value();
        TreeStats s = structure.stats();
        TriangleIntersector triangles = new TriangleIntersector(mesh);
        RayQuery query = structure.query(triangles);
        double traceSeconds;
        try (RayBatch batch = new RayBatch(1, () -> query)) {
            traceSeconds = Timing.median(1, runs, Timing.QUIET, () -> batch.trace(rays)).seconds();
        }
        TraversalStats counts = RayBatch.count(structure, triangles, rays, countedRays);
        double perRay = Math.max(1, counts.rays);
        return new TradeoffResult(v.name(), settings, build.millis(), s.expectedCost(), s.nodes(),
                s.leaves(), s.memoryBytes(), counts.nodes / perRay, counts.primitiveTests / perRay, counts.boxTests / perRay,
                rays.size() / traceSeconds, mesh.size());
    }

    /**
     * The Pareto front of build time against trace time: results no other result beats on both
     * (at least as fast to build and to trace, and faster on one).
     *
     * @param results the measurements
     * @return for each result, in order, whether it is on the front
     */
    public static boolean[] paretoFront(List<TradeoffResult> results) {
        boolean[] front = new boolean[results.size()];
        for (int i = 0; i < front.length; i++) {
            TradeoffResult a = results.get(i);
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
    public static String csv(List<TradeoffResult> results) {
        boolean[] front = paretoFront(results);
        StringBuilder sb = new StringBuilder(TradeoffResult.csvHeader()).append('\n');
        for (int i = 0; i < results.size(); i++) sb.append(results.get(i).csvRow(front[i])).append('\n');
        return sb.toString();
    }
}
