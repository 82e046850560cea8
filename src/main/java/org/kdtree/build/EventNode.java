package org.kdtree.build;

import org.kdtree.geom.Box;

/**
 * A node of the O(N log N) SAH build (Wald and Havran 2006, section 4.3): besides the
 * references and clipped bounds, one list of events per axis, sorted by position.
 *
 * <p>An event is a position and an int code {@code j << 2 | kind}, where {@code j} is the
 * reference's index in this node and kind is {@link #END}, {@link #PLANAR} or {@link #START}.
 * A reference whose clipped bounds are flat on an axis has one planar event there, any other
 * a start (at its clipped minimum) and an end (at its clipped maximum): the same events the
 * sort-per-node search builds from scratch. The k lists share two flat arrays; the list of
 * axis a is {@code [axisStart[a], axisStart[a + 1])}.
 */
final class EventNode extends BuildNode {
    static final int END = 0, PLANAR = 1, START = 2;

    private double[] pos;
    private int[] code;
    private final int[] axisStart;

    EventNode(Box voxel, int[] refs, double[] clipped, int depth, double[] pos, int[] code, int[] axisStart) {
        super(voxel, refs, clipped, depth);
        this.pos = pos;
        this.code = code;
        this.axisStart = axisStart;
    }

    /** The events of a node made by the default partition: built from its clipped bounds and sorted. */
    static EventNode of(BuildNode node, boolean parallel) {
        int k = node.dimension(), n = node.size();
        double[] clipped = node.clippedBounds();
        int[] start = new int[k + 1];
        for (int a = 0; a < k; a++) start[a + 1] = start[a] + eventCount(clipped, k, n, a);
        double[] pos = new double[start[k]];
        int[] code = new int[start[k]];
        Runnable[] axes = new Runnable[k];
        for (int a = 0; a < k; a++) {
            int axis = a;
            axes[a] = () -> {
                int m = start[axis];
                for (int j = 0; j < n; j++) m = addEvents(clipped, k, j, j, axis, pos, code, m);
                EventSort.sort(pos, code, start[axis], start[axis + 1]);
            };
        }
        if (parallel) java.util.Arrays.stream(axes).parallel().forEach(Runnable::run);
        else for (Runnable r : axes) r.run();
        return new EventNode(node.voxel(), node.refs(), clipped, node.depth(), pos, code, start);
    }

    /** The number of events of {@code n} references on {@code axis}: one per flat, two per other. */
    static int eventCount(double[] clipped, int k, int n, int axis) {
        int m = 0;
        for (int j = 0; j < n; j++) m += clipped[2 * k * j + axis] == clipped[2 * k * j + k + axis] ? 1 : 2;
        return m;
    }

    /** Appends the events of the reference at {@code j} in {@code clipped}, coded as index {@code id}. */
    static int addEvents(double[] clipped, int k, int j, int id, int axis, double[] pos, int[] code, int m) {
        double lo = clipped[2 * k * j + axis], hi = clipped[2 * k * j + k + axis];
        if (lo == hi) {
            pos[m] = lo;
            code[m++] = id << 2 | PLANAR;
        } else {
            pos[m] = lo;
            code[m++] = id << 2 | START;
            pos[m] = hi;
            code[m++] = id << 2 | END;
        }
        return m;
    }

    /** The sorted event positions of all axes (the node's own array). */
    double[] positions() { return pos; }

    /** The event codes, in the order of {@link #positions}. */
    int[] codes() { return code; }

    /** Where the events of {@code axis} begin; they end where the next axis's begin. */
    int axisStart(int axis) { return axisStart[axis]; }

    @Override protected void release() {
        super.release();
        pos = null;
        code = null;
    }
}
