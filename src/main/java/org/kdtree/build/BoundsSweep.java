package org.kdtree.build;

import java.util.Arrays;

/**
 * The exact plane search for a small node held as references with clipped bounds
 * ({@link NodeStore#BOUNDS}), without turning it into events: per axis, its starts, ends and
 * planar positions are sorted in scratch arrays of the store, then swept by
 * {@link SortedPlaneSearch#sweep}. The same candidates in the same order as the event sweep, so
 * the same plane; O(n log n) per node, which for the few references of a node near the leaves
 * is cheaper than keeping events sorted through every split. Allocates nothing.
 */
final class BoundsSweep {
    private BoundsSweep() {
    }

    /** Offers every candidate plane of child c of level d (held in the bounds form) to {@code best}. */
    static void search(NodeStore store, int d, int c, SahCost sah, SahSplit best) {
        int k = store.k, n = store.boundsMeta(d)[2 * c + 1], at = store.boundsMeta(d)[2 * c];
        double[] bounds = store.bounds(d);
        double[] scratch = store.sortPositions(3 * n);
        for (int axis = 0; axis < k; axis++) {
            int ns = 0, np = 0;
            for (int j = 0, o = 2 * k * at + axis; j < n; j++, o += 2 * k) {
                double lo = bounds[o], hi = bounds[o + k];
                if (lo == hi) scratch[2 * n + np++] = lo;
                else {
                    scratch[ns] = lo;
                    scratch[n + ns++] = hi;
                }
            }
            Arrays.sort(scratch, 0, ns);
            Arrays.sort(scratch, n, n + ns);
            Arrays.sort(scratch, 2 * n, 2 * n + np);
            SortedPlaneSearch.sweep(sah, best, axis, n, scratch, 0, scratch, n, ns, scratch, 2 * n, np);
        }
    }
}
