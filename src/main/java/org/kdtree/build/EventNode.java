package org.kdtree.build;

import org.kdtree.geom.Box;

/**
 * A node of the O(N log N) SAH build (Wald and Havran 2006, section 4.3): its references and
 * one list of events per axis, sorted by position.
 *
 * <p>An event is a position and an int code {@code j << 2 | kind}, where {@code j} is the
 * reference's index in this node and kind is {@link #END}, {@link #PLANAR} or {@link #START}.
 * A reference whose clipped bounds are flat on an axis has one planar event there, any other
 * a start (at its clipped minimum) and an end (at its clipped maximum): the same events the
 * sort-per-node search builds from scratch. The events of axis a are
 * {@code [eventsFrom(a), eventsTo(a))} of the shared arrays {@link #positions()} and
 * {@link #codes()}; below the root, those arrays belong to an {@link EventArena} level.
 *
 * <p>The events are the clipped bounds, so the node keeps no other copy of them: the build
 * never needs one, and {@link #clippedMin} and friends recover them from the events (once, in
 * O(events), for code outside the hot path that asks).
 */
final class EventNode extends BuildNode {
    static final int END = 0, PLANAR = 1, START = 2;

    private double[] pos;
    private int[] code;
    /** from and to of each axis's events: {@code range[2a], range[2a + 1]}. */
    private final int[] range;
    /** Where this node's children are written. */
    private final EventArena arena;

    private double[] clipped;

    EventNode(Box voxel, int[] refs, int base, int size, int depth,
              double[] pos, int[] code, int[] range, EventArena arena) {
        super(voxel, refs, null, base, size, depth);
        this.pos = pos;
        this.code = code;
        this.range = range;
        this.arena = arena;
    }

    /** The events of a node made by the default partition: built from its clipped bounds and sorted. */
    static EventNode of(BuildNode node, boolean parallel) {
        int k = node.dimension(), n = node.size();
        double[] clipped = node.clippedBounds();
        int[] range = new int[2 * k];
        for (int a = 0, m = 0; a < k; a++) {
            range[2 * a] = m;
            m += eventCount(clipped, k, n, a);
            range[2 * a + 1] = m;
        }
        double[] pos = new double[range[2 * k - 1]];
        int[] code = new int[pos.length];
        Runnable[] axes = new Runnable[k];
        for (int a = 0; a < k; a++) {
            int axis = a;
            axes[a] = () -> {
                int m = range[2 * axis];
                for (int j = 0; j < n; j++) m = addEvents(clipped, k, j, j, axis, pos, code, m);
                EventSort.sort(pos, code, range[2 * axis], range[2 * axis + 1]);
            };
        }
        if (parallel) java.util.Arrays.stream(axes).parallel().forEach(Runnable::run);
        else for (Runnable r : axes) r.run();
        return new EventNode(node.voxel(), node.refs(), 0, n, node.depth(), pos, code, range, new EventArena(k));
    }

    /** The same node, whose descendants are written into fresh scratch memory (for another thread). */
    EventNode detached() {
        return new EventNode(voxel(), refArray(), base(), size(), depth(), pos, code, range, new EventArena(dimension()));
    }

    @Override public double clippedMin(int j, int axis) {
        return clippedBounds()[2 * dimension() * j + axis];
    }

    @Override public double clippedMax(int j, int axis) {
        return clippedBounds()[2 * dimension() * j + dimension() + axis];
    }

    /** The clipped bounds, recovered from the events on first use. */
    @Override public double[] clippedBounds() {
        if (clipped == null) {
            int k = dimension();
            double[] c = new double[2 * k * size()];
            for (int a = 0; a < k; a++) {
                for (int e = eventsFrom(a); e < eventsTo(a); e++) {
                    int j = code[e] >>> 2, kind = code[e] & 3;
                    if (kind != END) c[2 * k * j + a] = pos[e];
                    if (kind != START) c[2 * k * j + k + a] = pos[e];
                }
            }
            clipped = c;
        }
        return clipped;
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

    /** The sorted event positions (shared with other nodes: use {@link #eventsFrom}, {@link #eventsTo}). */
    double[] positions() { return pos; }

    /** The event codes, in the order of {@link #positions}. */
    int[] codes() { return code; }

    /** Where the events of {@code axis} begin. */
    int eventsFrom(int axis) { return range[2 * axis]; }

    /** Where the events of {@code axis} end. */
    int eventsTo(int axis) { return range[2 * axis + 1]; }

    /** The scratch memory this node's children are written into. */
    EventArena arena() { return arena; }

    @Override protected void release() {
        super.release();
        pos = null;
        code = null;
        clipped = null;
    }
}
