package org.kdtree.measure;

import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Supplier;
import org.kdtree.accel.AccelerationStructure;
import org.kdtree.accel.Hit;
import org.kdtree.accel.PacketQuery;
import org.kdtree.accel.RayPacket;
import org.kdtree.accel.RayQuery;
import org.kdtree.accel.TraversalStats;
import org.kdtree.geom.Ray;
import org.kdtree.limits.Limits;

/**
 * The one ray-batch tracer: traces a {@link RaySet} (closest hit of every ray) on one or more
 * threads, each with its own query object made up front, and returns the benchmark's checksum.
 * Used by {@code raycast} and the trade-off study alike, with one interval convention:
 * t in (0, +infinity), as docs/benchmark-spec.md defines it ({@link #T_MIN}).
 *
 * <p>Rays are handed out in blocks of 4096; hit counts and t sums are kept per block and added in
 * block order, so the checksum is the same for any thread count. Given a structure, the rays of an
 * image (set P) are traced in tiles of 8 x 8 as packets ({@link AccelerationStructure#packetQuery}:
 * every structure answers them; {@link #describeLoops} says how), and summed in the same order:
 * the same checksum either way. Given only single-ray queries, every set goes one ray at a time.
 */
public final class RayBatch implements AutoCloseable {
    /**
     * The lower end of every ray's interval: the smallest positive double, so that the interval is
     * the spec's open (0, +infinity) and a hit at t = 0 (a ray starting on a triangle) is not counted.
     */
    public static final double T_MIN = Double.MIN_VALUE;

    private static final int BLOCK = 4096;
    /** The edge of a tile of an image's rays traced as one packet: 8 x 8 measured best (docs/performance.md). */
    static final int TILE = RayPacket.TILE;

    /**
     * The spec's checksum of one pass.
     *
     * @param hits how many rays hit
     * @param tSum the sum of their hit distances, added in ray order by block
     */
    public record Checksum(long hits, double tSum) {
    }

    private final RayQuery[] queries;
    /** Per thread, its packet query; null when only single rays are traced. */
    private final PacketQuery[] packets;
    private final ExecutorService pool;

    /**
     * A tracer with {@code threads} query objects from {@code factory} (one per thread), each ray
     * traced alone.
     *
     * @param threads threads tracing each set ({@link Limits#THREADS})
     * @param factory makes a query object (each thread needs its own)
     */
    public RayBatch(int threads, Supplier<? extends RayQuery> factory) {
        this(threads, factory, null);
    }

    /**
     * A tracer of {@code structure} on {@code threads} threads: an image's rays (set P) in packets
     * through its packet queries, other sets one ray at a time through its queries.
     *
     * @param threads   threads tracing each set ({@link Limits#THREADS})
     * @param structure the structure traced, over a 3-D triangle mesh
     */
    public RayBatch(int threads, AccelerationStructure structure) {
        this(threads, structure::query, structure::packetQuery);
    }

    private RayBatch(int threads, Supplier<? extends RayQuery> factory, Supplier<PacketQuery> packetFactory) {
        Limits.THREADS.check(Limits.THREADS.title(), threads);
        queries = new RayQuery[threads];
        for (int i = 0; i < threads; i++) queries[i] = factory.get();
        packets = packetFactory == null ? null : new PacketQuery[threads];
        if (packets != null) for (int i = 0; i < threads; i++) packets[i] = packetFactory.get();
        pool = threads > 1 ? Executors.newFixedThreadPool(threads, r -> {
            Thread t = new Thread(r, "ray-batch");
            t.setDaemon(true);
            return t;
        }) : null;
    }

    /**
     * Traces every ray once.
     *
     * @param rays the rays
     * @return how many hit, and the sum of their hit distances
     */
    public Checksum trace(RaySet rays) {
        int n = rays.size(), blocks = (n + BLOCK - 1) / BLOCK;
        long[] hits = new long[blocks];
        double[] sums = new double[blocks];
        AtomicInteger next = new AtomicInteger();
        if (packets != null && rays.imageWidth() > 0) {
            double[] t = new double[n];
            run(packets, q -> tiles(q, rays, next, t));
            sumInBlocks(t, hits, sums);
        } else {
            run(queries, q -> work(q, rays, next, hits, sums));
        }
        long h = 0;
        double s = 0;
        for (int b = 0; b < blocks; b++) { h += hits[b]; s += sums[b]; }
        return new Checksum(h, s);
    }

    /**
     * {@return how it traces each kind of set, for a report}: one ray at a time, and for an image's
     * rays, packets through a packet loop or each ray alone through the single-ray loop
     */
    public String describeLoops() {
        if (packets == null) return "every ray alone, through the single-ray loop";
        return "rays not of an image (set R) alone, through the single-ray loop; an image's rays (set P) in 8 x 8 packets, "
                + (packets[0].tracesTogether() ? "through the packet loop" : "each ray alone through the single-ray loop (no packet loop)");
    }

    /**
     * {@return the loop that traces {@code rays}, in a few words, for a study's engine column}:
     * single rays, or for an image's rays 8 x 8 packets through a packet loop or each ray alone
     * @param rays a ray set
     */
    public String loopOf(RaySet rays) {
        if (packets == null || rays.imageWidth() <= 0) return "single rays";
        return packets[0].tracesTogether() ? "8 x 8 packets through the packet loop" : "8 x 8 packets each ray alone";
    }

    /** Runs {@code job} with each thread's query, on the pool's threads or this one. */
    private <Q extends RayQuery> void run(Q[] each, java.util.function.Consumer<Q> job) {
        if (pool == null) {
            job.accept(each[0]);
            return;
        }
        Future<?>[] f = new Future<?>[each.length];
        for (int i = 0; i < each.length; i++) {
            Q q = each[i];
            f[i] = pool.submit(() -> job.accept(q));
        }
        try {
            for (Future<?> x : f) x.get();
        } catch (ExecutionException e) {
            throw e.getCause() instanceof RuntimeException r ? r : new IllegalStateException(e.getCause());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new java.util.concurrent.CancellationException("tracing interrupted");
        }
    }

    /**
     * Traces an image's rays in tiles of {@link #TILE} x {@link #TILE} pixels, one packet each,
     * bands of {@link #TILE} rows handed out in turn; writes each ray's hit distance (NaN for a miss) to {@code t}.
     */
    private static void tiles(PacketQuery pq, RaySet rays, AtomicInteger next, double[] t) {
        RayPacket packet = new RayPacket();
        int[] pixel = new int[TILE * TILE];
        double[] r = rays.raw();
        int w = rays.imageWidth(), h = rays.size() / w;
        for (int band; (band = next.getAndIncrement()) * TILE < h; ) {
            int y0 = band * TILE, y1 = Math.min(h, y0 + TILE);
            for (int x0 = 0; x0 < w; x0 += TILE) {
                int x1 = Math.min(w, x0 + TILE);
                packet.clear();
                int n = RayPacket.tileOrder(x1 - x0, y1 - y0, w, pixel), corner = y0 * w + x0;
                for (int j = 0; j < n; j++) {
                    pixel[j] += corner;
                    int o = 6 * pixel[j];
                    packet.add(r[o], r[o + 1], r[o + 2], r[o + 3], r[o + 4], r[o + 5], T_MIN, Double.POSITIVE_INFINITY);
                }
                pq.closestHits(packet);
                for (int i = 0; i < n; i++) t[pixel[i]] = packet.found(i) ? packet.t[i] : Double.NaN;
            }
        }
    }

    /** The checksum of each block from the rays' hit distances, added in ray order as {@link #work} adds them. */
    private static void sumInBlocks(double[] t, long[] hits, double[] sums) {
        for (int b = 0; b < hits.length; b++) {
            long h = 0;
            double s = 0;
            for (int i = b * BLOCK, end = Math.min(t.length, i + BLOCK); i < end; i++) {
                if (t[i] == t[i]) {
                    h++;
                    s += t[i];
                }
            }
            hits[b] = h;
            sums[b] = s;
        }
    }

    private static void work(RayQuery q, RaySet rays, AtomicInteger next, long[] hits, double[] sums) {
        Ray ray = new Ray(3);
        Hit hit = new Hit();
        double[] r = rays.raw();
        int n = rays.size();
        for (int b; (b = next.getAndIncrement()) * BLOCK < n; ) {
            long h = 0;
            double s = 0;
            for (int i = b * BLOCK, end = Math.min(n, i + BLOCK); i < end; i++) {
                int o = 6 * i;
                ray.set(r[o], r[o + 1], r[o + 2], r[o + 3], r[o + 4], r[o + 5]);
                if (q.closestHit(ray, T_MIN, Double.POSITIVE_INFINITY, hit)) {
                    h++;
                    s += hit.t;
                }
            }
            hits[b] = h;
            sums[b] = s;
        }
    }

    /**
     * Traces about {@code limit} rays spread over the whole set with a listener that counts nodes
     * visited, primitive tests and box tests (same interval as {@link #trace}).
     *
     * @param structure the kd-tree or bounding volume hierarchy that finds each ray's closest hit
     * @param set       the rays to sample, every {@code size / limit}-th one
     * @param limit     about how many rays to trace
     * @return the counts summed over the rays traced
     */
    public static TraversalStats count(AccelerationStructure structure, RaySet set, int limit) {
        double[] r = set.raw();
        int n = set.size();
        // Every stride-th ray, so the sample spans the whole set: the first rows of the primary
        // set P are sky, and counting only them would report zero nodes per ray.
        int stride = Math.max(1, n / Math.max(1, limit));
        Ray ray = new Ray(3);
        Hit hit = new Hit();
        TraversalStats stats = new TraversalStats();
        RayQuery counting = structure.query(stats);
        for (int i = 0; i < n; i += stride) {
            int o = 6 * i;
            ray.set(r[o], r[o + 1], r[o + 2], r[o + 3], r[o + 4], r[o + 5]);
            counting.closestHit(ray, T_MIN, Double.POSITIVE_INFINITY, hit);
        }
        return stats;
    }

    @Override public void close() {
        if (pool != null) pool.shutdownNow();
    }
}
