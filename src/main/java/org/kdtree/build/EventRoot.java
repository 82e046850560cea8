package org.kdtree.build;

import org.kdtree.geom.Box;

/**
 * The root of the event engine's tree, or of a subtree handed to it: every reference's clipped
 * bounds become its events (a planar event where the bounds are flat on an axis, else a start
 * and an end), sorted once per axis. At the root of a parallel build the axes are sorted in
 * parallel.
 */
final class EventRoot {
    private EventRoot() {
    }

    /** Writes the root of the whole build (child 0 of level 0): every primitive with its own bounds. */
    static void write(EventEngine engine, Box rootVoxel) {
        int k = engine.k, n = engine.prims.size();
        double[] bounds = new double[2 * k * n], voxel = new double[2 * k];
        Partition.writeAllBounds(engine.prims, bounds);
        for (int a = 0; a < k; a++) {
            voxel[a] = rootVoxel.min(a);
            voxel[k + a] = rootVoxel.max(a);
        }
        write(engine, 0, voxel, 0, null, 0, bounds, 0, n, java.util.concurrent.ForkJoinTask.inForkJoinPool());
    }

    /**
     * Writes a node as child 0 of level {@code d}: the voxel at {@code voxel[voxelAt ..]} (k minima,
     * k maxima), the {@code n} references {@code refs[refsAt ..]} (null: primitives 0 .. n-1) with
     * their clipped bounds at slots {@code boundsAt ..} of {@code bounds}.
     */
    static void write(EventEngine engine, int d, double[] voxel, int voxelAt, int[] refs, int refsAt,
                      double[] bounds, int boundsAt, int n, boolean parallel) {
        int k = engine.k;
        EventLevels levels = engine.levels;
        int[] meta = levels.meta(d);
        meta[0] = n;
        int total = 0;
        for (int a = 0; a < k; a++) {
            meta[1 + 2 * a] = total;
            total += eventCount(bounds, boundsAt, k, n, a);
            meta[2 + 2 * a] = total;
        }
        levels.reserve(d, total);
        System.arraycopy(voxel, voxelAt, levels.voxel(d), 0, 2 * k);
        double[] pos = levels.positions(d);
        int[] code = levels.codes(d);
        Runnable[] axes = new Runnable[k];
        for (int a = 0; a < k; a++) {
            int axis = a, from = meta[1 + 2 * a], to = meta[2 + 2 * a];
            axes[a] = () -> {
                int m = from;
                for (int j = 0; j < n; j++)
                    m = addEvents(bounds, k, boundsAt + j, refs == null ? j : refs[refsAt + j], axis, pos, code, m);
                if (parallel) EventSort.sort(pos, code, from, to, new double[to - from], new int[to - from]);
                else EventSort.sort(pos, code, from, to, engine.sortPositions(to - from), engine.sortCodes());
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
