package org.kdtree.kdtree;

import org.kdtree.geom.Box;
import org.kdtree.geom.OutwardFloat;
import org.kdtree.shape.Primitives;

/**
 * The split step of Algorithm 1 for a node held in the float form ({@link NodeStore#FLOATS}):
 * as {@link BoundsSplit}, over one float array per coordinate. A float bound is the exact one
 * rounded to nearest: a reference whose floats' rounding intervals lie on one side of the plane
 * is on that side; one nearer (or straddling) is decided by its exact bounds, its own first,
 * then, if they cross the plane, by the exact clip ({@link Partition#clipStraddler}).
 * No primitive is lost. Both children are written into level d + 1, the left one from slot 0,
 * the right one from slot n (a node of n references), in node order; nothing is allocated once
 * the levels have grown.
 *
 * <p>Rounded to nearest, not outwards, so that two triangles meeting at a vertex v end and start
 * at the same float, as their exact bounds do at v, and the small-node sweep sees the plane that
 * separates them; the plane is then put at v itself, or past the float's rounding ({@link #exactPlane}). (Rounded outwards they
 * end at up(v) and start at down(v): no float plane separates them, and on the bunny the fast
 * build made 6.6 % more references and took 1.12 x as long.)
 */
final class FloatSplit {
    private static final int LEFT = 1, RIGHT = 2, STRADDLES = 3, NEAR = 4;

    private final NodeStore store;
    private final int k;
    private final Box voxel, clipLeft, clipRight, own;
    /** Per reference of the node being split, its slot in the left child and in the right (or a slot past both where it goes to neither, or was written already). */
    private int[] toLeft = new int[0], toRight = new int[0];

    FloatSplit(NodeStore store) {
        this.store = store;
        this.k = store.k;
        this.voxel = new Box(k);
        this.own = new Box(k);
        this.clipLeft = new Box(k);
        this.clipRight = new Box(k);
    }

    /** Splits child c of level d by {@code x_axis = xi} (or at {@link #exactPlane}); returns the {@link SplitOutcome}, writing nothing unless SPLIT. */
    int split(int d, int c, int axis, double xi, boolean planarLeft, boolean perfectSplits) {
        int[] meta = store.boundsMeta(d);
        int from = meta[2 * c], n = meta[2 * c + 1];
        float[][] f = store.floats(d);
        float[] lo = f[axis], hi = f[k + axis];
        store.voxel(d, c, voxel);
        xi = exactPlane(store.refs(d), lo, hi, from, n, axis, xi);
        store.splitAt = xi;
        int nl = n;                           // room for n left, then n right, then a slot for writes to nowhere
        store.reserveFloats(d + 1, 2 * n + 1);
        long sizes = partition(d, from, n, axis, xi, planarLeft, perfectSplits, nl);
        int sizeL = (int) (sizes >>> 32), sizeR = (int) sizes;
        int outcome = SplitOutcome.of(n, sizeL, sizeR, store.budget(d)[c]);
        if (outcome != SplitOutcome.SPLIT) return outcome;
        int[] meta1 = store.boundsMeta(d + 1);
        meta1[0] = 0;
        meta1[1] = sizeL;
        meta1[2] = nl;
        meta1[3] = sizeR;
        store.writeChildren(d, c, axis, xi, sizeL, sizeR, NodeStore.FLOATS);
        return SplitOutcome.SPLIT;
    }

    /**
     * The side of float bounds [lo, hi], each the exact bound rounded to nearest: LEFT if
     * {@code hi <= leftUpTo} (then the exact maximum is at most the plane), RIGHT if
     * {@code lo >= rightFrom}, STRADDLES if the exact bounds surely lie on both sides, else NEAR
     * (the exact bounds decide).
     */
    private static int side(float lo, float hi, float leftUpTo, float rightFrom) {
        if (hi <= leftUpTo) return LEFT;
        if (lo >= rightFrom) return RIGHT;
        if (lo < leftUpTo && hi > rightFrom) return STRADDLES;
        return NEAR;
    }

    /** The largest float whose rounding interval (up to the midpoint to the next float) ends at or before {@code xi}. */
    private static float leftUpTo(double xi) {
        float t = OutwardFloat.down(xi);
        return mid(t, Math.nextUp(t)) <= xi ? t : Math.nextDown(t);
    }

    /** The smallest float whose rounding interval (from the midpoint to the float before) starts at or after {@code xi}. */
    private static float rightFrom(double xi) {
        float u = OutwardFloat.up(xi);
        return mid(Math.nextDown(u), u) >= xi ? u : Math.nextUp(u);
    }

    /** The midpoint of two floats, exact in a double. */
    private static double mid(float a, float b) {
        return ((double) a + b) / 2;
    }

    /**
     * The plane a search of float bounds meant, at a float p (a bound of some references): where
     * references only end at p (their exact maxima round to p), at the midpoint to the next float,
     * past all of them; where they only start, at the midpoint to the float before;
     * where some end and some start (a vertex v they share, on the bunny), between the largest of
     * their own exact maxima and the smallest minimum, if each of those rounds to p; else p. A
     * plane at p itself would cut by a sliver each reference whose exact bound lies on its far
     * side, and send it to both children, where the exact search puts it on one. The split is
     * right wherever the plane lies; this only spares it those slivers.
     */
    private double exactPlane(int[] refs, float[] lo, float[] hi, int from, int n, int axis, double xi) {
        float p = (float) xi;
        if (p != xi) return xi;    // a bin boundary, not a bound
        boolean anyEnd = false, anyStart = false;
        for (int j = from; j < from + n; j++) {
            boolean ends = hi[j] == p, starts = lo[j] == p;
            if (ends && starts) return xi;   // lies in the plane, as the search counted it
            anyEnd |= ends;
            anyStart |= starts;
        }
        double x;
        if (anyEnd && !anyStart) x = mid(p, Math.nextUp(p));
        else if (anyStart && !anyEnd) x = mid(Math.nextDown(p), p);
        else if (anyEnd) x = shared(refs, lo, hi, from, n, axis, p);
        else return xi;
        return x > voxel.min(axis) && x < voxel.max(axis) ? x : xi;
    }

    /** Between the own exact maxima of the references ending at p and the minima of those starting there, if each rounds to p; else p. */
    private double shared(int[] refs, float[] lo, float[] hi, int from, int n, int axis, float p) {
        double endsAt = Double.NEGATIVE_INFINITY, startsAt = Double.POSITIVE_INFINITY;
        for (int j = from; j < from + n; j++) {
            boolean ends = hi[j] == p;
            if (!ends && lo[j] != p) continue;
            store.prims.bounds(refs[j], own);
            double x = ends ? own.max(axis) : own.min(axis);
            if ((float) x != p) return p;   // clipped there: its exact bound is not known here
            if (ends) endsAt = Math.max(endsAt, x);
            else startsAt = Math.min(startsAt, x);
        }
        return endsAt <= startsAt ? endsAt : p;
    }

    /**
     * Writes the references {@code [from, from + n)} of level d into level d + 1, the left
     * child's from slot 0 and the right one's from slot {@code nl} (= n); returns the children's sizes
     * as {@code left << 32 | right} (a straddler's clip may miss a child its bounds touched). In
     * 3-D each reference's bounds are moved as it is classified; in other dimensions its slots
     * in the children are noted, and the bounds moved one coordinate array at a time after.
     */
    private long partition(int d, int from, int n, int axis, double xi, boolean planarLeft, boolean perfect, int nl) {
        int[] refs = store.refs(d), outRefs = store.refs(d + 1);
        float[][] in = store.floats(d), out = store.floats(d + 1);
        float[] lo = in[axis], hi = in[k + axis];
        float below = leftUpTo(xi), above = rightFrom(xi), at = (float) xi;
        if (toLeft.length < n) { toLeft = new int[NodeStore.grown(toLeft.length, n)]; toRight = new int[toLeft.length]; }
        int[] tl = toLeft, tr = toRight;
        int il = 0, ir = nl, nowhere = nl + n;
        boolean three = k == 3;   // 3-D: each one-sided reference's six floats moved at once, through local arrays
        float[] i0 = in[0], i1 = in[1], i2 = in[2 % (2 * k)], i3 = in[3 % (2 * k)], i4 = in[4 % (2 * k)], i5 = in[5 % (2 * k)];
        float[] l0 = out[0], l1 = out[1], l2 = out[2 % (2 * k)], l3 = out[3 % (2 * k)], l4 = out[4 % (2 * k)], l5 = out[5 % (2 * k)];
        for (int j = from, i = 0; j < from + n; j++, i++) {
            int prim = refs[j];
            int s = side(lo[j], hi[j], below, above);
            if (s == NEAR) {
                store.prims.bounds(prim, own);   // near the plane in floats: the exact bounds decide
                s = switch (Partition.classify(own.min(axis), own.max(axis), xi, planarLeft)) {
                    case LEFT -> LEFT;
                    case RIGHT -> RIGHT;
                    case BOTH -> STRADDLES;
                };
            }
            tl[i] = nowhere;
            tr[i] = nowhere;
            if (s == LEFT) {
                outRefs[il] = prim;
                if (three) {
                    l0[il] = i0[j]; l1[il] = i1[j]; l2[il] = i2[j]; l3[il] = i3[j]; l4[il] = i4[j]; l5[il] = i5[j];
                    il++;
                } else {
                    tl[i] = il++;
                }
            } else if (s == RIGHT) {
                outRefs[ir] = prim;
                if (three) {
                    l0[ir] = i0[j]; l1[ir] = i1[j]; l2[ir] = i2[j]; l3[ir] = i3[j]; l4[ir] = i4[j]; l5[ir] = i5[j];
                    ir++;
                } else {
                    tr[i] = ir++;
                }
            } else if (!perfect) {    // the bounds cut by each child voxel
                for (int a = 0; a < 2 * k; a++) out[a][il] = out[a][ir] = in[a][j];
                out[k + axis][il] = Math.min(hi[j], at);
                out[axis][ir] = Math.max(lo[j], at);
                outRefs[il++] = prim;
                outRefs[ir++] = prim;
            } else {
                int to = Partition.clipStraddler(store.prims, prim, voxel, axis, xi, clipLeft, clipRight);
                if ((to & 1) != 0) { write(clipLeft, out, il); outRefs[il++] = prim; }
                if ((to & 2) != 0) { write(clipRight, out, ir); outRefs[ir++] = prim; }
            }
        }
        for (int a = 0; !three && a < 2 * k; a++) {
            float[] src = in[a], dst = out[a];
            for (int i = 0; i < n; i++) {   // no branch: a side a reference does not go to is written at nowhere
                float v = src[from + i];
                dst[tl[i]] = v;
                dst[tr[i]] = v;
            }
        }
        return (long) il << 32 | (ir - nl);
    }

    /** Writes {@code b} rounded to nearest at slot {@code at} of {@code dest}. */
    private static void write(Box b, float[][] dest, int at) {
        int k = b.dimension();
        for (int a = 0; a < k; a++) {
            dest[a][at] = (float) b.min(a);
            dest[k + a][at] = (float) b.max(a);
        }
    }

    /** Every primitive's own bounds rounded to nearest, the root's: slot i of {@code dest} for primitive i. */
    static void writeAllBounds(Primitives prims, float[][] dest) {
        Box b = new Box(prims.dimension());
        for (int i = 0; i < prims.size(); i++) {
            prims.bounds(i, b);
            write(b, dest, i);
        }
    }
}
