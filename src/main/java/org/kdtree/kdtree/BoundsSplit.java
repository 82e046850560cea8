package org.kdtree.kdtree;

import org.kdtree.geom.Box;

/**
 * The split step of Algorithm 1 for a node held as references with clipped bounds
 * ({@link NodeStore#BOUNDS}): {@code T_L = { t in T | t overlaps V_L }}, {@code T_R} likewise.
 * Each reference goes where {@link Partition#classify} sends it; a straddler gets its bounds
 * clipped to each child it reaches ({@link Partition#straddlerBounds}). Both children are
 * written into level d + 1 in node order (so in increasing order of primitive): the left one
 * from slot 0, the right one after room for every left candidate. Nothing is allocated once
 * the levels have grown.
 */
final class BoundsSplit {
    private final NodeStore store;
    private final int k;
    private final Box voxel, clipLeft, clipRight;

    BoundsSplit(NodeStore store) {
        this.store = store;
        this.k = store.k;
        this.voxel = new Box(k);
        this.clipLeft = new Box(k);
        this.clipRight = new Box(k);
    }

    /** Splits child c of level d by {@code x_axis = xi}; returns the {@link SplitOutcome}, writing nothing unless SPLIT. */
    int split(int d, int c, int axis, double xi, boolean planarLeft, boolean perfectSplits) {
        int[] meta = store.boundsMeta(d);
        int from = meta[2 * c], n = meta[2 * c + 1];
        double[] bounds = store.bounds(d);
        int nl = 0, nr = 0;
        for (int j = from, o = 2 * k * from + axis; j < from + n; j++, o += 2 * k) {
            Partition.Side s = Partition.classify(bounds[o], bounds[o + k], xi, planarLeft);
            if (s != Partition.Side.RIGHT) nl++;
            if (s != Partition.Side.LEFT) nr++;
        }
        store.reserveBounds(d + 1, nl + nr);
        store.voxel(d, c, voxel);
        long sizes = partition(d, from, n, axis, xi, planarLeft, perfectSplits, nl);
        int sizeL = (int) (sizes >>> 32), sizeR = (int) sizes;
        int outcome = SplitOutcome.of(n, sizeL, sizeR, store.budget(d)[c]);
        if (outcome != SplitOutcome.SPLIT) return outcome;
        int[] below = store.boundsMeta(d + 1);
        below[0] = 0;
        below[1] = sizeL;
        below[2] = nl;
        below[3] = sizeR;
        store.writeChildren(d, c, axis, xi, sizeL, sizeR, NodeStore.BOUNDS);
        return SplitOutcome.SPLIT;
    }

    /**
     * Writes the references {@code [from, from + n)} of level d into level d + 1, the left
     * child's from slot 0 and the right one's from slot {@code nl}; returns the children's sizes
     * as {@code left << 32 | right} (a straddler's clip may miss a child its bounds touched).
     */
    private long partition(int d, int from, int n, int axis, double xi, boolean planarLeft, boolean perfect, int nl) {
        int[] refs = store.refs(d), outRefs = store.refs(d + 1);
        double[] bounds = store.bounds(d), outBounds = store.bounds(d + 1);
        int il = 0, ir = nl;
        for (int j = from; j < from + n; j++) {
            int prim = refs[j];
            switch (Partition.classify(bounds[2 * k * j + axis], bounds[2 * k * j + k + axis], xi, planarLeft)) {
                case LEFT -> { outRefs[il] = prim; System.arraycopy(bounds, 2 * k * j, outBounds, 2 * k * il++, 2 * k); }
                case RIGHT -> { outRefs[ir] = prim; System.arraycopy(bounds, 2 * k * j, outBounds, 2 * k * ir++, 2 * k); }
                case BOTH -> {
                    int to = Partition.straddlerBounds(store.prims, prim, bounds, j, voxel, axis, xi, perfect, clipLeft, clipRight,
                            outBounds, il, outBounds, ir);
                    if ((to & 1) != 0) outRefs[il++] = prim;
                    if ((to & 2) != 0) outRefs[ir++] = prim;
                }
            }
        }
        return (long) il << 32 | (ir - nl);
    }
}
