package org.kdtree.cli;

import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Supplier;
import org.kdtree.geom.Ray;
import org.kdtree.limits.Limits;
import org.kdtree.traverse.Hit;
import org.kdtree.traverse.RayQuery;
import org.kdtree.tradeoff.RaySet;

/**
 * Traces a ray set (closest hit, t in (0, +inf)) on one or more threads, each with its own query
 * object made before timing. Rays are handed out in blocks of 4096; hit counts and t sums are
 * kept per block and added in block order, so the checksum is the same for any thread count.
 */
final class RayBatch implements AutoCloseable {
    private static final int BLOCK = 4096;

    /** The checksum of one pass. */
    record Result(long hits, double tSum, double seconds) {
    }

    private final RayQuery[] queries;
    private final ExecutorService pool;

    RayBatch(int threads, Supplier<RayQuery> factory) {
        Limits.THREADS.check("--threads", threads);
        queries = new RayQuery[threads];
        for (int i = 0; i < threads; i++) queries[i] = factory.get();
        pool = threads > 1 ? Executors.newFixedThreadPool(threads, r -> {
            Thread t = new Thread(r, "raycast");
            t.setDaemon(true);
            return t;
        }) : null;
    }

    /** One pass over all rays. */
    Result trace(RaySet rays) throws Exception {
        int n = rays.size(), blocks = (n + BLOCK - 1) / BLOCK;
        long[] hits = new long[blocks];
        double[] sums = new double[blocks];
        AtomicInteger next = new AtomicInteger();
        long t0 = System.nanoTime();
        if (pool == null) {
            work(queries[0], rays, next, hits, sums);
        } else {
            Future<?>[] f = new Future<?>[queries.length];
            for (int i = 0; i < queries.length; i++) {
                RayQuery q = queries[i];
                f[i] = pool.submit(() -> work(q, rays, next, hits, sums));
            }
            for (Future<?> x : f) x.get();
        }
        double seconds = (System.nanoTime() - t0) / 1e9;
        long h = 0;
        double s = 0;
        for (int b = 0; b < blocks; b++) { h += hits[b]; s += sums[b]; }
        return new Result(h, s, seconds);
    }

    private static void work(RayQuery q, RaySet rays, AtomicInteger next, long[] hits, double[] sums) {
        Ray ray = new Ray(3);
        Hit hit = new Hit();
        double[] r = rays.rays();
        int n = rays.size();
        for (int b; (b = next.getAndIncrement()) * BLOCK < n; ) {
            long h = 0;
            double s = 0;
            for (int i = b * BLOCK, end = Math.min(n, i + BLOCK); i < end; i++) {
                int o = 6 * i;
                ray.set(r[o], r[o + 1], r[o + 2], r[o + 3], r[o + 4], r[o + 5]);
                if (q.closestHit(ray, Double.MIN_VALUE, Double.POSITIVE_INFINITY, hit)) {
                    h++;
                    s += hit.t;
                }
            }
            hits[b] = h;
            sums[b] = s;
        }
    }

    @Override public void close() {
        if (pool != null) pool.shutdownNow();
    }
}
