package org.kdtree.build;

/**
 * The scratch memory of the event engine, one per depth, reused by every node of that depth,
 * so that a split allocates nothing.
 *
 * <p>The recursion is depth-first and a split at depth d writes both children into level
 * d + 1: the left child, then the right. While the left subtree is built (levels d + 2 and
 * deeper), the right child waits untouched in level d + 1; when another node writes to level
 * d + 1, everything that lived there is finished. A level is therefore overwritten, or
 * replaced by bigger arrays, only when its contents are dead. Peak memory is that of the
 * pending right children along one path: about twice the root's events.
 *
 * <p>Child c (0 left, 1 right) of level d has its voxel at {@code voxel(d)[2k c ..]} (k minima,
 * then k maxima), its size at {@code meta(d)[metaAt(c)]}, and the events of axis a from
 * {@code meta(d)[metaAt(c) + 1 + 2a]} to the next entry, in {@code positions(d)} and
 * {@code codes(d)}.
 */
final class EventLevels {
    private final int k;
    private final double[][] pos = new double[KdTreeBuilder.DEPTH_LIMIT + 2][];
    private final int[][] code = new int[KdTreeBuilder.DEPTH_LIMIT + 2][];
    private final int[][] meta = new int[KdTreeBuilder.DEPTH_LIMIT + 2][];
    private final double[][] voxel = new double[KdTreeBuilder.DEPTH_LIMIT + 2][];
    private final long[][] budget = new long[KdTreeBuilder.DEPTH_LIMIT + 2][];
    /** The depth of the subtree's root this memory serves: level d is kept in slot d - base. */
    private int base;

    EventLevels(int k) {
        this.k = k;
    }

    /**
     * Serves a subtree whose root lies at depth {@code depth} from now on, in the slots the last
     * subtree used from its root down: an engine reused for subtree after subtree (forked to
     * another thread) keeps reusing the same arrays whatever the depth it starts at.
     */
    void rebase(int depth) {
        base = depth;
    }

    /** Makes room for {@code count} events in level {@code d} (its old contents are dead). */
    void reserve(int d, int count) {
        int i = d - base;
        if (pos[i] == null || pos[i].length < count) {
            int n = grown(pos[i] == null ? 0 : pos[i].length, count);
            pos[i] = new double[n];
            code[i] = new int[n];
        }
    }

    double[] positions(int d) { return pos[d - base]; }

    int[] codes(int d) { return code[d - base]; }

    int[] meta(int d) {
        int[] m = meta[d - base];
        if (m == null) meta[d - base] = m = new int[2 * (2 * k + 1)];
        return m;
    }

    double[] voxel(int d) {
        double[] v = voxel[d - base];
        if (v == null) voxel[d - base] = v = new double[4 * k];
        return v;
    }

    /** Where child c's entries begin in {@link #meta}. */
    int metaAt(int c) { return (2 * k + 1) * c; }

    /**
     * Copies child c of level d (its voxel, size and events) into the same place of {@code other},
     * rebased so that level d is its first slot.
     */
    void copyChild(int d, int c, EventLevels other) {
        int[] m = meta(d);
        int at = metaAt(c), from = m[at + 1], to = m[at + 2 * k];
        other.rebase(d);
        other.reserve(d, to - from);
        System.arraycopy(positions(d), from, other.positions(d), 0, to - from);
        System.arraycopy(codes(d), from, other.codes(d), 0, to - from);
        int[] om = other.meta(d);
        om[at] = m[at];
        for (int i = 1; i <= 2 * k; i++) om[at + i] = m[at + i] - from;
        System.arraycopy(voxel(d), 2 * k * c, other.voxel(d), 2 * k * c, 2 * k);
        other.budget(d)[c] = budget(d)[c];
    }

    /** The reference budgets ({@link ReferenceBudget}) of the two children of level d. */
    long[] budget(int d) {
        if (budget[d - base] == null) budget[d - base] = new long[2];
        return budget[d - base];
    }

    static int grown(int current, int needed) {
        return (int) Math.min(Integer.MAX_VALUE - 8, Math.max(needed, current + (current >> 1) + 16L));
    }
}
