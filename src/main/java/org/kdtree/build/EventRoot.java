package org.kdtree.build;

import org.kdtree.geom.Box;

/**
 * The root of the event engine: every primitive's bounds become its events (a planar event
 * where the bounds are flat on an axis, else a start and an end), sorted once per axis. With
 * several threads the axes are sorted in parallel.
 */
final class EventRoot {
    private EventRoot() {
    }

    /** Writes the root (child 0 of level 0) into the engine's levels. */
    static void write(EventEngine engine, Box rootVoxel) {
        int k = engine.k, n = engine.prims.size();
        double[] bounds = bounds(engine, n);
        int[] meta = engine.levels.meta(0);
        meta[0] = n;
        int total = 0;
        for (int a = 0; a < k; a++) {
            meta[1 + 2 * a] = total;
            total += eventCount(bounds, k, n, a);
            meta[2 + 2 * a] = total;
        }
        engine.levels.reserve(0, total);
        double[] pos = engine.levels.positions(0);
        int[] code = engine.levels.codes(0);
        double[] voxel = engine.levels.voxel(0);
        for (int a = 0; a < k; a++) {
            voxel[a] = rootVoxel.min(a);
            voxel[k + a] = rootVoxel.max(a);
        }
        Runnable[] axes = new Runnable[k];
        for (int a = 0; a < k; a++) {
            int axis = a, from = meta[1 + 2 * a], to = meta[2 + 2 * a];
            axes[a] = () -> {
                int m = from;
                for (int j = 0; j < n; j++) m = addEvents(bounds, k, j, j, axis, pos, code, m);
                EventSort.sort(pos, code, from, to);
            };
        }
        if (java.util.concurrent.ForkJoinTask.inForkJoinPool()) java.util.Arrays.stream(axes).parallel().forEach(Runnable::run);
        else for (Runnable r : axes) r.run();
    }

    /** The bounds of every primitive, {@code 2k} values each, as the recursion's root holds them. */
    private static double[] bounds(EventEngine engine, int n) {
        int k = engine.k;
        double[] bounds = new double[2 * k * n];
        Box b = new Box(k);
        for (int i = 0; i < n; i++) {
            engine.prims.bounds(i, b);
            Partition.write(b, bounds, i);
        }
        return bounds;
    }

    /** The number of events of {@code n} references on {@code axis}: one per flat, two per other. */
    static int eventCount(double[] bounds, int k, int n, int axis) {
        int m = 0;
        for (int j = 0; j < n; j++) m += bounds[2 * k * j + axis] == bounds[2 * k * j + k + axis] ? 1 : 2;
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
