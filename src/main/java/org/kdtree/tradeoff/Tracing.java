package org.kdtree.tradeoff;

import org.kdtree.geom.Ray;
import org.kdtree.traverse.Hit;
import org.kdtree.traverse.RayQuery;
import org.kdtree.traverse.TraversalStats;
import org.kdtree.traverse.Traverser;

/** Traces a {@link RaySet} with a {@link Traverser}: closest hit for every ray. */
public final class Tracing {
    private Tracing() {
    }

    /** Hits and the sum of hit distances: the spec's checksum. */
    public record Checksum(long hits, double tSum) {
    }

    /**
     * Traces every ray (with a Traverser: its fast path, no listener) and returns the checksum.
     *
     * @param traverser finds each ray's closest hit
     * @param set       the rays, each traced over t in [0, infinity)
     * @return how many rays hit, and the sum of their hit distances
     */
    public static Checksum trace(RayQuery traverser, RaySet set) {
        double[] r = set.rays();
        Ray ray = new Ray(3);
        Hit hit = new Hit();
        long hits = 0;
        double sum = 0;
        for (int i = 0; i < r.length; i += 6) {
            ray.set(r[i], r[i + 1], r[i + 2], r[i + 3], r[i + 4], r[i + 5]);
            if (traverser.closestHit(ray, 0, Double.POSITIVE_INFINITY, hit)) {
                hits++;
                sum += hit.t;
            }
        }
        return new Checksum(hits, sum);
    }

    /**
     * Traces about {@code limit} rays spread over the whole set with a listener that counts nodes visited and triangle tests.
     *
     * @param traverser finds each ray's closest hit
     * @param set       the rays to sample, every {@code size / limit}-th one
     * @param limit     about how many rays to trace
     * @return the counts summed over the rays traced
     */
    public static TraversalStats count(Traverser traverser, RaySet set, int limit) {
        double[] r = set.rays();
        int n = r.length / 6;
        // Every stride-th ray, so the sample spans the whole set: the first rows of the primary
        // set P are sky, and counting only them would report zero nodes per ray.
        int stride = Math.max(1, n / Math.max(1, limit));
        Ray ray = new Ray(3);
        Hit hit = new Hit();
        TraversalStats stats = new TraversalStats();
        for (int i = 0; i < n; i += stride) {
            int o = 6 * i;
            ray.set(r[o], r[o + 1], r[o + 2], r[o + 3], r[o + 4], r[o + 5]);
            traverser.closestHit(ray, 0, Double.POSITIVE_INFINITY, hit, stats);
        }
        return stats;
    }
}
