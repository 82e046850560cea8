package org.kdtree.cli;

import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.atomic.AtomicLong;
import org.kdtree.accel.AccelerationStructure;
import org.kdtree.accel.Hit;
import org.kdtree.accel.TriangleIntersector;
import org.kdtree.geom.Ray;
import org.kdtree.geom.Tolerance;
import org.kdtree.measure.RaySet;

/**
 * The hidden {@code raycast --verify STRIDE}: traces every STRIDE-th ray of a set both by brute
 * force (double precision, every triangle, {@link TriangleIntersector#closestHitAll}) and through the structure (kd-tree or BVH), and counts disagreements: hit
 * versus miss, or closest t differing by more than 1e-9 relative. Slow by design (N rays times
 * all triangles); only the brute force runs on several threads, each with its own tree query.
 */
final class BruteCheck {
    private final TriangleIntersector tris;
    private final AccelerationStructure tree;
    private final int stride, threads;

    BruteCheck(TriangleIntersector tris, AccelerationStructure tree, int stride, int threads) {
        this.tris = tris;
        this.tree = tree;
        this.stride = stride;
        this.threads = Math.max(1, threads);
    }

    String compare(RaySet rays) throws Exception {
        int n = rays.size();
        AtomicLong checked = new AtomicLong(), bruteHits = new AtomicLong(), treeHits = new AtomicLong(),
                mismatches = new AtomicLong();
        double[] sums = new double[2 * threads];
        ExecutorService pool = Executors.newFixedThreadPool(threads);
        try {
            Future<?>[] f = new Future<?>[threads];
            double[] r = rays.rays();   // one copy, read by every thread
            for (int th = 0; th < threads; th++) {
                int id = th;
                var own = tree.query();
                f[th] = pool.submit(() -> {
                    Ray ray = new Ray(3);
                    Hit a = new Hit(), b = new Hit();
                    for (int i = id * stride; i < n; i += threads * stride) {
                        int o = 6 * i;
                        ray.set(r[o], r[o + 1], r[o + 2], r[o + 3], r[o + 4], r[o + 5]);
                        boolean x = tris.closestHitAll(ray, Double.MIN_VALUE, Double.POSITIVE_INFINITY, a);
                        boolean y = own.closestHit(ray, Double.MIN_VALUE, Double.POSITIVE_INFINITY, b);
                        checked.incrementAndGet();
                        if (x) { bruteHits.incrementAndGet(); sums[2 * id] += a.t; }
                        if (y) { treeHits.incrementAndGet(); sums[2 * id + 1] += b.t; }
                        if (x != y || (x && !Tolerance.DEFAULT.equal(a.t, b.t))) {
                            if (mismatches.incrementAndGet() <= 5)
                                System.err.println("# mismatch ray " + i + " " + ray + ": brute " + a + ", tree " + b);
                        }
                    }
                });
            }
            for (Future<?> x : f) x.get();
        } finally {
            pool.shutdownNow();
        }
        double bs = 0, ts = 0;
        for (int th = 0; th < threads; th++) { bs += sums[2 * th]; ts += sums[2 * th + 1]; }
        return String.format(java.util.Locale.ROOT,
                "%d rays (every %d-th): brute force %d hits, tsum %.6f; tree %d hits, tsum %.6f; %d disagree",
                checked.get(), stride, bruteHits.get(), bs, treeHits.get(), ts, mismatches.get());
    }
}
