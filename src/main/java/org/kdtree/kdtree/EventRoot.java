package org.kdtree.kdtree;

/**
 * A node turned from references with clipped bounds into the SAH's sorted events (Wald and
 * Havran 2006, section 4.3): the root of an event build, or a node below the binned SAH's
 * exact threshold. Every reference's clipped bounds become its events (a planar event where the
 * bounds are flat on an axis, else a start and an end), sorted once per axis; below, the splits
 * keep them sorted ({@link EventSplit}). At the root of a parallel build the axes are sorted in
 * parallel. One sort serves every node: {@link EventSort}, events packed in longs.
 */
final class EventRoot {
    private EventRoot() {
    }

    /**
     * Writes child c of level d as events, from its {@code n} references {@code refs[at ..]} whose
     * clipped bounds are at the same slots of {@code bounds}; its voxel and budget stay where they are.
     */
    static void write(NodeStore store, int d, int c, int[] refs, int at, double[] bounds, int n, boolean parallel) {
        int k = store.k;
        int[] meta = store.eventMeta(d);
        int m0 = store.metaAt(c);
        meta[m0] = n;
        int total = 0;
        for (int a = 0; a < k; a++) {
            meta[m0 + 1 + 2 * a] = total;
            total += eventCount(bounds, at, k, n, a);
            meta[m0 + 2 + 2 * a] = total;
        }
        store.reserveEvents(d, total);
        double[] pos = store.positions(d);
        int[] code = store.codes(d);
        Runnable[] axes = new Runnable[k];
        for (int a = 0; a < k; a++) {
            int axis = a, from = meta[m0 + 1 + 2 * a], to = meta[m0 + 2 + 2 * a];
            axes[a] = () -> {
                for (int j = 0, m = from; j < n; j++) m = addEvents(bounds, k, at + j, refs[at + j], axis, pos, code, m);
                (parallel ? new EventSort() : store.sort).sort(pos, code, from, to);
            };
        }
        if (parallel) java.util.Arrays.stream(axes).parallel().forEach(Runnable::run);
        else for (Runnable r : axes) r.run();
    }

    /** The number of events of {@code n} references (bounds from slot {@code at}) on {@code axis}: one per flat, two per other. */
    private static int eventCount(double[] bounds, int at, int k, int n, int axis) {
        int m = 0;
        for (int j = at; j < at + n; j++) m += bounds[2 * k * j + axis] == bounds[2 * k * j + k + axis] ? 1 : 2;
        return m;
    }

    /** Appends the events on {@code axis} of the bounds at slot {@code j} for {@code primitive}; returns the new end. */
    static int addEvents(double[] bounds, int k, int j, int primitive, int axis, double[] pos, int[] code, int m) {
        double lo = bounds[2 * k * j + axis], hi = bounds[2 * k * j + k + axis];
        if (lo == hi) {
            pos[m] = lo;
            code[m++] = EventCode.of(EventCode.PLANAR, primitive);
        } else {
            pos[m] = lo;
            code[m++] = EventCode.of(EventCode.START, primitive);
            pos[m] = hi;
            code[m++] = EventCode.of(EventCode.END, primitive);
        }
        return m;
    }
}
