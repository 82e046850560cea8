package org.kdtree.kdtree;

import org.kdtree.geom.Box;
import org.kdtree.shape.Primitives;

/**
 * The one node store of a build: the scratch memory of the recursion, one level per depth,
 * reused by every node of that depth, so that a split allocates nothing and no node owns an
 * array. Every builder runs over it, the library's and a student's.
 *
 * <p>The recursion is depth-first and a split at depth d writes both children into level
 * d + 1: the left child (c = 0), then the right (c = 1). While the left subtree is built
 * (levels d + 2 and deeper), the right child waits untouched in level d + 1; when another node
 * writes to level d + 1, everything that lived there is finished. A level is therefore
 * overwritten, or replaced by bigger arrays, only when its contents are dead.
 *
 * <p>A node is held in one of two forms:
 * <ul>
 * <li>{@link #BOUNDS}: a slice of the level's references with their clipped bounds at the
 * same slots ({@code 2k} values a slot: k minima, then k maxima); child c starts at
 * {@code boundsMeta(d)[2c]} and holds {@code boundsMeta(d)[2c + 1]} references, in increasing
 * order. Every node starts so; {@link BoundsSplit} keeps it so.</li>
 * <li>{@link #EVENTS}: the SAH's sorted events (Wald and Havran 2006, section 4.3), a
 * position and an {@link EventCode} each; child c's size is at {@code eventMeta(d)[metaAt(c)]}
 * and its events on axis a run from {@code eventMeta(d)[metaAt(c) + 1 + 2a]} to the next
 * entry. A node is turned into this form when a plane search asks for its events
 * ({@link #events}); {@link EventSplit} keeps its children so.</li>
 * </ul>
 * Child c's voxel is at {@code voxel(d)[2k c ..]} (k minima, then k maxima) and its share of
 * the reference budget at {@code budget(d)[c]}, whatever its form.
 *
 * <p>One store serves one thread of work: the whole build, or a subtree handed to another
 * thread, which gets an idle store of the build ({@link #copyChild}).
 */
final class NodeStore {
    /** The forms a node is held in. */
    static final byte BOUNDS = 0, EVENTS = 1;

    final int k;
    final Primitives prims;
    private final int levels = KdTreeBuilder.DEPTH_LIMIT + 2;
    private final double[][] voxel = new double[levels][];
    private final long[][] budget = new long[levels][];
    private final byte[][] form = new byte[levels][];
    private final int[][] refs = new int[levels][];
    private final double[][] bounds = new double[levels][];
    private final int[][] boundsMeta = new int[levels][];
    private final double[][] pos = new double[levels][];
    private final int[][] code = new int[levels][];
    private final int[][] eventMeta = new int[levels][];
    /** The depth of the subtree's root this memory serves: level d is kept in slot d - base. */
    private int base;

    /** The view the builder's methods see, pointed at one node after another. */
    final BuildNode view;
    /** The nodes this store has served: paces the recursion's look at its thread's interrupt flag. */
    int nodes;
    /** Per primitive, a slot or a side: scratch of the event split and of {@link BuildNode}'s bounds of an event node. */
    private int[] slotOf;
    private int[] leafRefs = new int[16];
    /** The one sort of this thread's events ({@link EventSort}), with its scratch. */
    final EventSort sort = new EventSort();
    private int[] minBin = new int[0], maxBin = new int[0];
    private EventSplit eventSplit;
    private BoundsSplit boundsSplit;
    /** What a builder keeps with this store ({@link BuildNode#state}): one object, of the builder's own type. */
    Object state;

    NodeStore(Primitives prims) {
        this.prims = prims;
        this.k = prims.dimension();
        this.view = new BuildNode(this);
    }

    /** Writes the root, child 0 of level 0: every primitive with its own bounds, in {@code rootVoxel}, with {@code budget}. */
    void writeRoot(Box rootVoxel, long rootBudget) {
        int n = prims.size();
        base = 0;
        reserveBounds(0, n);
        int[] r = refs(0);
        for (int i = 0; i < n; i++) r[i] = i;
        Partition.writeAllBounds(prims, bounds(0));
        int[] m = boundsMeta(0);
        m[0] = 0;
        m[1] = n;
        form(0)[0] = BOUNDS;
        double[] v = voxel(0);
        for (int a = 0; a < k; a++) {
            v[a] = rootVoxel.min(a);
            v[k + a] = rootVoxel.max(a);
        }
        budget(0)[0] = rootBudget;
    }

    // ---- what every form has ----

    /** {@return |T| of child c of level d} */
    int size(int d, int c) {
        return form(d)[c] == BOUNDS ? boundsMeta(d)[2 * c + 1] : eventMeta(d)[metaAt(c)];
    }

    /** {@return the form of child c of level d} */
    byte formOf(int d, int c) { return form(d)[c]; }

    byte[] form(int d) {
        byte[] f = form[d - base];
        if (f == null) form[d - base] = f = new byte[2];
        return f;
    }

    double[] voxel(int d) {
        double[] v = voxel[d - base];
        if (v == null) voxel[d - base] = v = new double[4 * k];
        return v;
    }

    /** The reference budgets ({@link ReferenceBudget}) of the two children of level d. */
    long[] budget(int d) {
        long[] b = budget[d - base];
        if (b == null) budget[d - base] = b = new long[2];
        return b;
    }

    /** {@return {@code dest}, set to the voxel of child c of level d} */
    Box voxel(int d, int c, Box dest) {
        double[] v = voxel(d);
        for (int a = 0; a < k; a++) dest.setMin(a, v[2 * k * c + a]).setMax(a, v[2 * k * c + k + a]);
        return dest;
    }

    /**
     * What every split writes for its two children into level d + 1, whatever their form: their
     * voxels (child c of level d's, cut at {@code x_axis = xi}), their shares of its reference
     * budget, and their form.
     */
    void writeChildren(int d, int c, int axis, double xi, int sizeL, int sizeR, byte childForm) {
        double[] v = voxel(d), below = voxel(d + 1);
        System.arraycopy(v, 2 * k * c, below, 0, 2 * k);
        System.arraycopy(v, 2 * k * c, below, 2 * k, 2 * k);
        below[k + axis] = xi;
        below[2 * k + axis] = xi;
        long budget = budget(d)[c];
        long[] shares = budget(d + 1);
        shares[0] = ReferenceBudget.share(budget, sizeL, sizeL, sizeR);
        shares[1] = ReferenceBudget.share(budget, sizeR, sizeL, sizeR);
        byte[] f = form(d + 1);
        f[0] = childForm;
        f[1] = childForm;
    }

    /**
     * Splits child c of level d by the plane {@code x_axis = xi} into both children in level
     * d + 1, in its own form, with their shares of its reference budget; returns the
     * {@link SplitOutcome}, and writes nothing unless it is {@link SplitOutcome#SPLIT}.
     */
    int split(int d, int c, int axis, double xi, boolean planarLeft, boolean perfectSplits) {
        if (form(d)[c] == EVENTS) {
            if (eventSplit == null) eventSplit = new EventSplit(this);
            return eventSplit.split(d, c, axis, xi, planarLeft, perfectSplits);
        }
        if (boundsSplit == null) boundsSplit = new BoundsSplit(this);
        return boundsSplit.split(d, c, axis, xi, planarLeft, perfectSplits);
    }

    /** Writes child c of level d as a leaf: its primitives, in increasing order. */
    void leaf(int d, int c, org.kdtree.kdtree.KdTreeWriter out) {
        if (form(d)[c] == BOUNDS) {
            int[] m = boundsMeta(d);
            out.leaf(refs(d), m[2 * c], m[2 * c + 1]);
            return;
        }
        int n = leafRefs(d, c);
        out.leaf(leafRefs, 0, n);
    }

    /** Lists the primitives of event node c of level d (one start or planar event each on axis 0) in {@link #leafRefs()}, sorted; returns how many. */
    int leafRefs(int d, int c) {
        int n = size(d, c);
        if (leafRefs.length < n) leafRefs = new int[grown(leafRefs.length, n)];
        int[] cd = codes(d), meta = eventMeta(d);
        int at = metaAt(c), m = 0;
        for (int e = meta[at + 1], to = meta[at + 2]; e < to; e++)
            if (EventCode.kind(cd[e]) != EventCode.END) leafRefs[m++] = EventCode.primitive(cd[e]);
        java.util.Arrays.sort(leafRefs, 0, m);
        return m;
    }

    int[] leafRefs() { return leafRefs; }

    /**
     * Copies child c of level d (voxel, budget, and its references or events) into the same place
     * of {@code other}, rebased so that level d is its first slot; returns its size.
     */
    int copyChild(int d, int c, NodeStore other) {
        other.base = d;
        other.form(d)[c] = form(d)[c];
        System.arraycopy(voxel(d), 2 * k * c, other.voxel(d), 2 * k * c, 2 * k);
        other.budget(d)[c] = budget(d)[c];
        if (form(d)[c] == BOUNDS) {
            int[] m = boundsMeta(d);
            int from = m[2 * c], n = m[2 * c + 1];
            other.reserveBounds(d, n);
            System.arraycopy(refs(d), from, other.refs(d), 0, n);
            System.arraycopy(bounds(d), 2 * k * from, other.bounds(d), 0, 2 * k * n);
            int[] om = other.boundsMeta(d);
            om[2 * c] = 0;
            om[2 * c + 1] = n;
            return n;
        }
        int[] m = eventMeta(d);
        int at = metaAt(c), from = m[at + 1], to = m[at + 2 * k];
        other.reserveEvents(d, to - from);
        System.arraycopy(positions(d), from, other.positions(d), 0, to - from);
        System.arraycopy(codes(d), from, other.codes(d), 0, to - from);
        int[] om = other.eventMeta(d);
        om[at] = m[at];
        for (int i = 1; i <= 2 * k; i++) om[at + i] = m[at + i] - from;
        return m[at];
    }

    // ---- the bounds form ----

    /** Makes room for {@code count} references in level {@code d} (its old contents are dead). */
    void reserveBounds(int d, int count) {
        int i = d - base;
        if (refs[i] == null || refs[i].length < count) {
            int n = grown(refs[i] == null ? 0 : refs[i].length, count);
            refs[i] = new int[n];
            bounds[i] = new double[2 * k * n];
        }
    }

    int[] refs(int d) { return refs[d - base]; }

    double[] bounds(int d) { return bounds[d - base]; }

    int[] boundsMeta(int d) {
        int[] m = boundsMeta[d - base];
        if (m == null) boundsMeta[d - base] = m = new int[4];
        return m;
    }

    // ---- the event form ----

    /**
     * Child c of level d in the event form: turned into it from the bounds form if need be
     * (its events sorted once, {@link EventRoot}); at the root of a parallel build the axes are
     * sorted in parallel.
     */
    void events(int d, int c) {
        if (form(d)[c] == EVENTS) return;
        int[] m = boundsMeta(d);
        EventRoot.write(this, d, c, refs(d), m[2 * c], bounds(d), m[2 * c + 1],
                d == 0 && java.util.concurrent.ForkJoinTask.inForkJoinPool());
        form(d)[c] = EVENTS;
        if (view.level() == d && view.child() == c) view.formChanged();
    }

    /** Makes room for {@code count} events in level {@code d} (its old contents are dead). */
    void reserveEvents(int d, int count) {
        int i = d - base;
        if (pos[i] == null || pos[i].length < count) {
            int n = grown(pos[i] == null ? 0 : pos[i].length, count);
            pos[i] = new double[n];
            code[i] = new int[n];
        }
    }

    double[] positions(int d) { return pos[d - base]; }

    int[] codes(int d) { return code[d - base]; }

    int[] eventMeta(int d) {
        int[] m = eventMeta[d - base];
        if (m == null) eventMeta[d - base] = m = new int[2 * (2 * k + 1)];
        return m;
    }

    /** Where child c's entries begin in {@link #eventMeta}. */
    int metaAt(int c) { return (2 * k + 1) * c; }

    /** The binned SAH's histogram of minima, at least {@code bins} long (and as many maxima: {@link #maxBins}). */
    int[] minBins(int bins) {
        if (minBin.length < bins) {
            minBin = new int[bins];
            maxBin = new int[bins];
        }
        return minBin;
    }

    int[] maxBins() { return maxBin; }

    /** One int per primitive of the scene, for the caller to use as it likes until it returns. */
    int[] perPrimitive() {
        if (slotOf == null) slotOf = new int[prims.size()];
        return slotOf;
    }

    static int grown(int current, int needed) {
        return (int) Math.min(Integer.MAX_VALUE - 8, Math.max(needed, current + (current >> 1) + 16L));
    }
}
