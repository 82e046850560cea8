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
 * sort-per-node search builds from scratch.
 */
final class EventNode extends BuildNode {
    static final int END = 0, PLANAR = 1, START = 2;

    private double[][] pos;
    private int[][] code;

    EventNode(Box voxel, int[] refs, double[] clipped, int depth, double[][] pos, int[][] code) {
        super(voxel, refs, clipped, depth);
        this.pos = pos;
        this.code = code;
    }

    /** The events of a node made by the default partition: built from its clipped bounds and sorted. */
    static EventNode of(BuildNode node, boolean parallel) {
        int k = node.dimension();
        double[][] pos = new double[k][];
        int[][] code = new int[k][];
        Runnable[] axes = new Runnable[k];
        for (int a = 0; a < k; a++) {
            int axis = a;
            axes[a] = () -> {
                int m = eventCount(node.clippedBounds(), k, node.size(), axis);
                pos[axis] = new double[m];
                code[axis] = new int[m];
                fill(node.clippedBounds(), k, node.size(), axis, pos[axis], code[axis]);
                EventSort.sort(pos[axis], code[axis], m);
            };
        }
        if (parallel) java.util.Arrays.stream(axes).parallel().forEach(Runnable::run);
        else for (Runnable r : axes) r.run();
        return new EventNode(node.voxel(), node.refs(), node.clippedBounds(), node.depth(), pos, code);
    }

    /** The number of events of {@code n} references on {@code axis}: one per flat, two per other. */
    static int eventCount(double[] clipped, int k, int n, int axis) {
        int m = 0;
        for (int j = 0; j < n; j++) m += clipped[2 * k * j + axis] == clipped[2 * k * j + k + axis] ? 1 : 2;
        return m;
    }

    /** Writes the (unsorted) events of references {@code 0..n)} on {@code axis}; returns the count. */
    private static int fill(double[] clipped, int k, int n, int axis, double[] pos, int[] code) {
        int m = 0;
        for (int j = 0; j < n; j++) m = addEvents(clipped, k, j, j, axis, pos, code, m);
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

    /** The sorted event positions on {@code axis} (the node's own array). */
    double[] positions(int axis) { return pos[axis]; }

    /** The event codes on {@code axis}, in the order of {@link #positions}. */
    int[] codes(int axis) { return code[axis]; }

    @Override protected void release() {
        super.release();
        pos = null;
        code = null;
    }
}
