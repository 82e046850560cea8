package org.kdtree.build;

/**
 * The scratch memory of the binned engine, one per depth, reused as {@link EventLevels} is
 * (a split at depth d writes both children into level d + 1). A node is a slice of the
 * level's references with their clipped bounds at the same slots ({@code 2k} values a slot):
 * child c (0 left, 1 right) of level d starts at {@code meta(d)[2c]} and holds
 * {@code meta(d)[2c + 1]} references; its voxel is at {@code voxel(d)[2k c ..]}.
 */
final class BinnedLevels {
    private final int k;
    private final int[][] refs = new int[KdTreeBuilder.DEPTH_LIMIT + 2][];
    private final double[][] bounds = new double[KdTreeBuilder.DEPTH_LIMIT + 2][];
    private final int[][] meta = new int[KdTreeBuilder.DEPTH_LIMIT + 2][];
    private final double[][] voxel = new double[KdTreeBuilder.DEPTH_LIMIT + 2][];
    private final long[][] budget = new long[KdTreeBuilder.DEPTH_LIMIT + 2][];

    /** The depth of the subtree's root this memory serves: level d is kept in slot d - base ({@link EventLevels#rebase}). */
    private int base;

    BinnedLevels(int k) {
        this.k = k;
    }

    /** Makes room for {@code count} references in level {@code d} (its old contents are dead). */
    void reserve(int d, int count) {
        int i = d - base;
        if (refs[i] == null || refs[i].length < count) {
            int n = EventLevels.grown(refs[i] == null ? 0 : refs[i].length, count);
            refs[i] = new int[n];
            bounds[i] = new double[2 * k * n];
        }
    }

    int[] refs(int d) { return refs[d - base]; }

    double[] bounds(int d) { return bounds[d - base]; }

    int[] meta(int d) {
        if (meta[d - base] == null) meta[d - base] = new int[4];
        return meta[d - base];
    }

    double[] voxel(int d) {
        if (voxel[d - base] == null) voxel[d - base] = new double[4 * k];
        return voxel[d - base];
    }

    /** The reference budgets ({@link ReferenceBudget}) of the two children of level d. */
    long[] budget(int d) {
        if (budget[d - base] == null) budget[d - base] = new long[2];
        return budget[d - base];
    }

    /** Copies child c of level d (voxel, references, bounds) into the same place of {@code other}, rebased to start at d. */
    void copyChild(int d, int c, BinnedLevels other) {
        int[] m = meta(d);
        int from = m[2 * c], n = m[2 * c + 1];
        other.base = d;
        other.reserve(d, n);
        System.arraycopy(refs(d), from, other.refs(d), 0, n);
        System.arraycopy(bounds(d), 2 * k * from, other.bounds(d), 0, 2 * k * n);
        int[] om = other.meta(d);
        om[2 * c] = 0;
        om[2 * c + 1] = n;
        System.arraycopy(voxel(d), 2 * k * c, other.voxel(d), 2 * k * c, 2 * k);
        other.budget(d)[c] = budget(d)[c];
    }
}
