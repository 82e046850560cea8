package org.kdtree.kdtree;

import java.util.Arrays;
import org.kdtree.geom.Box;
import org.kdtree.geom.SplitPlane;

/**
 * The node T, V that {@link KdTreeBuilder#terminate} and {@link KdTreeBuilder#findPlane} are
 * asked about: its voxel, the primitives that overlap it, the bounds of their parts inside the
 * voxel ("clipped bounds"), and its depth.
 *
 * <p>A view over the build's node store, not an object of its own: the recursion points one
 * view at one node after another, so a builder reads a node only while its method runs, and
 * must not keep the view, its voxel or the arrays it hands out. What a builder wants to carry
 * from its {@code terminate} to its {@code findPlane} on the same node it keeps with
 * {@link #keepPlane} (the SAH finds its best plane once, to decide both).
 *
 * <p>The j-th reference ({@code 0 <= j < size()}) is primitive {@link #ref(int) ref(j)}; the
 * references are listed in increasing order of primitive.
 */
public final class BuildNode {
    private final NodeStore store;
    private final Box voxel;
    private final int k;
    private int d, c, size, trials;
    private boolean voxelFilled, onTrial;
    private SplitPlane kept;
    /**
     * Where the node's references and clipped bounds are read, from slot {@link #from}: the
     * store's level arrays, or (for a node held as events) arrays made from its events when
     * first asked for; null until then.
     */
    private int[] refArray;
    private double[] boundsArray;
    private int from;
    private int[] eventRefs = new int[0];
    private double[] eventBounds = new double[0];
    private double[] scratch = new double[16];
    /** The node's events, once asked for ({@link #eventCount}): the store's arrays and each axis's stretch of them; null until then. */
    private double[] eventPos;
    private int[] eventCode;
    private final int[] eventFrom, eventTo;

    BuildNode(NodeStore store) {
        this.store = store;
        this.k = store.k;
        this.voxel = new Box(k);
        this.eventFrom = new int[k];
        this.eventTo = new int[k];
    }

    /** Points this view at child c of level d of its store, below {@code trialSplits} trial splits; forgets the kept plane. */
    BuildNode point(int depth, int child, int trialSplits) {
        d = depth;
        c = child;
        size = store.size(d, c);
        trials = trialSplits;
        kept = null;
        onTrial = false;
        voxelFilled = false;
        refArray = null;
        boundsArray = null;
        eventPos = null;
        return this;
    }

    /** The node's form changed (the store turned it into events): its arrays are read afresh when asked for. */
    void formChanged() {
        refArray = null;
        boundsArray = null;
    }

    /** Points {@link #refArray} and {@link #boundsArray} at the node's references and clipped bounds, in either form. */
    private void arrays() {
        if (store.formOf(d, c) == NodeStore.BOUNDS) {
            refArray = store.refs(d);
            boundsArray = store.bounds(d);
            from = store.boundsMeta(d)[2 * c];
        } else {
            makeEventBounds();
        }
    }

    /** {@return the voxel V of this node}; do not modify or keep it. */
    public Box voxel() {
        if (!voxelFilled) {
            store.voxel(d, c, voxel);
            voxelFilled = true;
        }
        return voxel;
    }

    /** {@return D(V), the depth of this node}; the root has depth 0. */
    public int depth() { return d; }

    /** {@return |T|, the number of primitives overlapping the voxel} */
    public int size() { return size; }

    /** {@return k, the dimension} */
    public int dimension() { return k; }

    /** {@return how many references this node's subtree may hold ({@link ReferenceBudget})} */
    public long budget() { return store.budget(d)[c]; }

    /**
     * {@return the index of the j-th primitive of this node}
     * @param j 0 .. {@link #size()} - 1
     */
    public int ref(int j) {
        if (j < 0 || j >= size) throw outside(j, 0);
        if (refArray == null) arrays();
        return refArray[from + j];
    }

    /**
     * {@return the lower bound on {@code axis} of the part of the j-th primitive inside the voxel}
     * @param j 0 .. {@link #size()} - 1
     * @param axis the axis, 0 .. {@link #dimension()} - 1
     */
    public double clippedMin(int j, int axis) {
        if (j < 0 || j >= size || axis < 0 || axis >= k) throw outside(j, axis);
        if (boundsArray == null) arrays();
        return boundsArray[2 * k * (from + j) + axis];
    }

    /**
     * {@return the upper bound on {@code axis} of the part of the j-th primitive inside the voxel}
     * @param j 0 .. {@link #size()} - 1
     * @param axis the axis, 0 .. {@link #dimension()} - 1
     */
    public double clippedMax(int j, int axis) {
        if (j < 0 || j >= size || axis < 0 || axis >= k) throw outside(j, axis);
        if (boundsArray == null) arrays();
        return boundsArray[2 * k * (from + j) + k + axis];
    }

    /** {@return the primitive indices, {@link #size()} of them, in a new array} */
    public int[] refs() {
        if (refArray == null) arrays();
        return Arrays.copyOfRange(refArray, from, from + size);
    }

    /** {@return the clipped bounds, {@code 2k} values per reference (k minima, then k maxima), in a new array} */
    public double[] clippedBounds() {
        if (boundsArray == null) arrays();
        return Arrays.copyOfRange(boundsArray, 2 * k * from, 2 * k * (from + size));
    }

    /**
     * Keeps {@code plane} for this node, so that {@code findPlane} can return what
     * {@code terminate} found (the SAH searches once to decide both); the next node starts
     * with nothing kept.
     * @param plane the plane to keep, or null to forget it
     */
    public void keepPlane(SplitPlane plane) {
        kept = plane;
        onTrial = false;
    }

    /**
     * Keeps {@code plane} as {@link #keepPlane} does, for a split made on trial (the talk's "a few
     * more iterations" past the point where the cost criterion says stop, which may be a local
     * minimum): the recursion builds the subtree below it, and keeps it only if its expected cost
     * ends below that of the leaf it replaces; otherwise the node becomes that leaf after all.
     * Its descendants see one more {@link #trialSplits()}.
     * @param plane the plane to try
     */
    public void keepTrialPlane(SplitPlane plane) {
        kept = plane;
        onTrial = true;
    }

    /** {@return whether the plane kept for this node is on trial ({@link #keepTrialPlane})} */
    boolean onTrial() { return onTrial; }

    /** {@return how many of the splits on the path from the root to this node were made on trial ({@link #keepTrialPlane})} */
    public int trialSplits() { return trials; }

    /** {@return the plane kept for this node by {@link #keepPlane}, or null} */
    public SplitPlane keptPlane() { return kept; }

    /**
     * {@return a scratch array of at least {@code length} doubles}, reused from node to node on
     * this thread (so a builder need not allocate per node); its contents are undefined, and it
     * is valid only until the builder's method returns.
     * @param length the number of values needed
     */
    public double[] scratch(int length) {
        if (scratch.length < length) scratch = new double[NodeStore.grown(scratch.length, length)];
        return scratch;
    }

    /**
     * {@return the object this builder keeps from node to node on this thread of the build
     * ({@link #keepState}), if it is a {@code type}; else null}: a plane search's state (the SAH
     * keeps its cost function and best plane so), which lives as long as the build, one per
     * thread, so that nothing need be allocated per node.
     * @param type what the builder keeps
     * @param <T> its type
     */
    public <T> T state(Class<T> type) {
        Object s = store.state;
        return type.isInstance(s) ? type.cast(s) : null;
    }

    /**
     * Keeps {@code state} from node to node on this thread of the build, for {@link #state} to return.
     * @param state what to keep (replacing what was kept)
     */
    public void keepState(Object state) { store.state = state; }

    // ---- the node's sorted events (Wald and Havran 2006, section 4.3) ----

    /** The kind of an event at a reference's clipped maximum. */
    public static final int END = EventCode.END;
    /** The kind of an event of a reference whose clipped bounds are flat on the axis (minimum = maximum). */
    public static final int PLANAR = EventCode.PLANAR;
    /** The kind of an event at a reference's clipped minimum. */
    public static final int START = EventCode.START;

    /**
     * {@return the number of this node's events on {@code axis}}: per reference a start and an
     * end, or one planar event, listed by increasing position. The first call on a node sorts its
     * events, once (the root's, or a node's below the binned search's threshold); its children
     * keep theirs sorted through the split, so a builder that sweeps them at every node builds in
     * O(N log N), as the library's SAH does ({@link EventSweep} reads the same arrays directly:
     * through these checked accessors the library's exact build measured about 5 % slower).
     * Read-only: the events are the clipped bounds, and belong to the store.
     * @param axis the axis, 0 .. {@link #dimension()} - 1
     */
    public int eventCount(int axis) {
        if (axis < 0 || axis >= k) throw outside(0, axis);
        if (eventPos == null) pointAtEvents();
        return eventTo[axis] - eventFrom[axis];
    }

    /** Turns the node into events if need be, and points the view's event arrays at them. */
    private void pointAtEvents() {
        store.events(d, c);
        int[] meta = store.eventMeta(d);
        int at = store.metaAt(c) + 1;
        for (int a = 0; a < k; a++) {
            eventFrom[a] = meta[at + 2 * a];
            eventTo[a] = meta[at + 2 * a + 1];
        }
        eventPos = store.positions(d);
        eventCode = store.codes(d);
    }

    /**
     * {@return the position of the i-th event on {@code axis}}, in increasing order of i;
     * call {@link #eventCount} on this node first
     * @param axis the axis
     * @param i 0 .. {@code eventCount(axis)} - 1
     */
    public double eventPosition(int axis, int i) {
        return eventPos[eventIndex(axis, i)];
    }

    /**
     * {@return the kind of the i-th event on {@code axis}: {@link #END}, {@link #PLANAR} or {@link #START}};
     * call {@link #eventCount} on this node first
     * @param axis the axis
     * @param i 0 .. {@code eventCount(axis)} - 1
     */
    public int eventKind(int axis, int i) {
        return EventCode.kind(eventCode[eventIndex(axis, i)]);
    }

    /**
     * {@return the primitive of the i-th event on {@code axis}}; call {@link #eventCount} on this node first
     * @param axis the axis
     * @param i 0 .. {@code eventCount(axis)} - 1
     */
    public int eventPrimitive(int axis, int i) {
        return EventCode.primitive(eventCode[eventIndex(axis, i)]);
    }

    private int eventIndex(int axis, int i) {
        if (eventPos == null || i < 0 || i >= eventTo[axis] - eventFrom[axis])
            throw new IndexOutOfBoundsException("event " + i + " on axis " + axis + " of a node "
                    + (eventPos == null ? "whose events were not asked for (call eventCount first)" : "of " + size));
        return eventFrom[axis] + i;
    }

    // ---- for the library's plane searches ----

    /** The array the node's clipped bounds are read from, in either form, from slot {@link #boundsFrom()} (2k values a slot). */
    double[] boundsArray() {
        if (boundsArray == null) arrays();
        return boundsArray;
    }

    /** The node's first slot in {@link #boundsArray()}. */
    int boundsFrom() {
        if (boundsArray == null) arrays();
        return from;
    }

    NodeStore store() { return store; }

    int level() { return d; }

    int child() { return c; }

    private IndexOutOfBoundsException outside(int j, int axis) {
        if (axis < 0 || axis >= k)
            return new IndexOutOfBoundsException("axis " + axis + " of a " + k + "-D node (valid: 0 .. " + (k - 1) + ")");
        return new IndexOutOfBoundsException("reference " + j + " of a node of " + size + " (valid: 0 .. " + (size - 1) + ")");
    }

    /** The references and clipped bounds of a node held as events: its primitives in order, their bounds from their events. */
    private void makeEventBounds() {
        int n = store.leafRefs(d, c);
        if (eventRefs.length < n) eventRefs = new int[n];
        if (eventBounds.length < 2 * k * n) eventBounds = new double[2 * k * n];
        int[] slot = store.perPrimitive();
        System.arraycopy(store.leafRefs(), 0, eventRefs, 0, n);
        for (int j = 0; j < n; j++) slot[eventRefs[j]] = j;
        double[] pos = store.positions(d);
        int[] code = store.codes(d), meta = store.eventMeta(d);
        int at = store.metaAt(c);
        for (int a = 0; a < k; a++) {
            for (int e = meta[at + 1 + 2 * a], to = meta[at + 2 + 2 * a]; e < to; e++) {
                int o = 2 * k * slot[EventCode.primitive(code[e])], kind = EventCode.kind(code[e]);
                if (kind != EventCode.END) eventBounds[o + a] = pos[e];
                if (kind != EventCode.START) eventBounds[o + k + a] = pos[e];
            }
        }
        refArray = eventRefs;
        boundsArray = eventBounds;
        from = 0;
    }
}
