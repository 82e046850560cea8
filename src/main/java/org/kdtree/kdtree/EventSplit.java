package org.kdtree.kdtree;

import org.kdtree.geom.Box;

/**
 * The split step of Algorithm 1 for a node held as sorted events ({@link NodeStore#EVENTS};
 * Wald and Havran 2006, section 4.3): classify each
 * primitive as left only, right only or straddling from the events on the split axis; clip
 * only the straddlers ({@link Partition#straddlerBounds}, as the recursion does); copy the
 * one-sided primitives' events, still sorted, into the children; sort the straddlers' few new
 * events and merge them in. Linear in the node's events plus {@code s log s} for {@code s}
 * straddlers, with nothing allocated: sides live in one byte per primitive, everything else
 * in the build's {@link NodeStore} and in scratch arrays kept from node to node.
 *
 * <p>Without perfect splits a straddler's box is only cut by the plane: its events on the other
 * axes stay as they are, and on the split axis its end in the left child and its start in the
 * right one become the plane. So its events are copied to both children in order, as the
 * one-sided ones are, and the plane's new events go at the end of the left list and the head of
 * the right one (every event left of the plane is at or below it, every one right of it at or
 * above): one pass, no bounds, no clipping, no sort (Sunflow's build works so; docs/sah.md).
 */
final class EventSplit {
    /** The side of a primitive in the node being split; a straddler's events are copied to neither child, or to both. */
    private static final byte STRADDLES = 0, LEFT = 1, RIGHT = 2, BOTH = 3;

    private final NodeStore store;
    private final int k;
    private final byte[] side;
    /** The straddlers' primitives, then per straddler bit 0 "goes left", bit 1 "goes right". */
    private int[] straddlers = new int[16], goesTo = new int[16];
    /** Clipped straddler bounds, 2k values a slot: slots [0, nb) the left child's, [nb, 2nb) the right's. */
    private double[] bounds = new double[0];
    /** One child's new events on one axis. */
    private double[] extraPos = new double[16];
    private int[] extraCode = new int[16];
    private final Box voxel, clipLeft, clipRight;

    EventSplit(NodeStore store) {
        this.store = store;
        this.k = store.k;
        this.side = new byte[store.prims.size()];
        this.voxel = new Box(k);
        this.clipLeft = new Box(k);
        this.clipRight = new Box(k);
    }

    /**
     * Splits child c of level d ({@code n} primitives) by the plane {@code x_axis = xi} into both
     * children in level d + 1, with their shares of its reference budget; returns the
     * {@link SplitOutcome}, and writes nothing unless it is {@link SplitOutcome#SPLIT}.
     */
    int split(int d, int c, int axis, double xi, boolean planarLeft, boolean perfectSplits) {
        int[] code = store.codes(d), meta = store.eventMeta(d);
        int at = store.metaAt(c), n = meta[at], from = meta[at + 1 + 2 * axis], to = meta[at + 2 + 2 * axis];
        if (straddlers.length < n) { straddlers = new int[n]; goesTo = new int[n]; }
        long counts = classify(store.positions(d), code, from, to, xi, planarLeft ? LEFT : RIGHT);
        int nl = (int) (counts >>> 32), nb = (int) counts, nr = n - nl - nb;
        long added = perfectSplits ? clipStraddlers(d, c, axis, xi, nb) : (long) nb << 32 | nb;   // uncut, a straddler goes both ways
        int sizeL = nl + (int) (added >>> 32), sizeR = nr + (int) added;
        int outcome = SplitOutcome.of(n, sizeL, sizeR, store.budget(d)[c]);
        if (outcome != SplitOutcome.SPLIT) return outcome;
        if (perfectSplits) writeChildEvents(d, c, nb, sizeL, sizeR);
        else copyChildEvents(d, c, axis, xi, nb, sizeL, sizeR);
        store.writeChildren(d, c, axis, xi, sizeL, sizeR, NodeStore.EVENTS);
        return SplitOutcome.SPLIT;
    }

    /**
     * The side of each primitive from its events on the split axis (its clipped bounds there),
     * the same decision as {@link Partition#classify}: a start at or after the plane means right
     * only, an end at or before it left only (its start came first and said straddles); a planar
     * event goes by its position, and to the chosen side when it lies in the plane. A primitive
     * whose end lies beyond the plane and whose start said straddles is a straddler: it goes to
     * {@link #straddlers}. Returns the number of left-only primitives and of straddlers, as
     * {@code left << 32 | straddlers}.
     */
    private long classify(double[] pos, int[] code, int from, int to, double xi, byte planarSide) {
        int left = 0, nb = 0;
        for (int e = from; e < to; e++) {
            int p = EventCode.primitive(code[e]);
            double x = pos[e];
            switch (EventCode.kind(code[e])) {
                case EventCode.START -> side[p] = x >= xi ? RIGHT : STRADDLES;
                case EventCode.END -> {
                    if (x <= xi) {
                        side[p] = LEFT;
                        left++;
                    } else if (side[p] == STRADDLES) straddlers[nb++] = p;
                }
                default -> {
                    byte s = x == xi ? planarSide : x < xi ? LEFT : RIGHT;
                    side[p] = s;
                    left += s & 1;
                }
            }
        }
        return (long) left << 32 | nb;
    }

    /**
     * Clips the {@code nb} straddlers to both children, into {@link #bounds}; records in
     * {@link #goesTo} which children each reaches (a clip can miss a child the bounds touched).
     * Returns how many go left and right, as {@code left << 32 | right}.
     */
    private long clipStraddlers(int d, int c, int axis, double xi, int nb) {
        if (nb == 0) return 0;
        store.voxel(d, c, voxel);
        if (bounds.length < 4 * k * nb) bounds = new double[NodeStore.grown(bounds.length, 4 * k * nb)];
        int left = 0, right = 0;
        for (int i = 0; i < nb; i++) {
            int to = Partition.straddlerBounds(store.prims, straddlers[i], null, 0, voxel, axis, xi,   // clipped: no parent bounds read
                    true, clipLeft, clipRight, bounds, i, bounds, nb + i);
            goesTo[i] = to;
            left += to & 1;
            right += to >>> 1;
        }
        return (long) left << 32 | right;
    }

    /** Writes both children's events with perfect splits: the one-sided ones copied, the clipped straddlers' merged in. */
    private void writeChildEvents(int d, int c, int nb, int sizeL, int sizeR) {
        writeChildren(d, c, nb, sizeL, sizeR, -1, 0);
    }

    /**
     * Writes both children's events without perfect splits (the class comment): the straddlers
     * marked {@link #BOTH}, their events copied with the one-sided ones, the plane's new ones added.
     */
    private void copyChildEvents(int d, int c, int axis, double xi, int nb, int sizeL, int sizeR) {
        for (int i = 0; i < nb; i++) side[straddlers[i]] = BOTH;
        writeChildren(d, c, nb, sizeL, sizeR, axis, xi);
    }

    /**
     * Writes both children's events into level d + 1: sizes, and per axis the events copied in
     * order, with the straddlers' clipped events merged in ({@code cut < 0}), or, uncut, the plane's
     * events added on axis {@code cut}. Each child's region on an axis is sized before anything is
     * copied: its events are among the node's plus at most two per straddler; one slot more for the
     * branch-free copy.
     */
    private void writeChildren(int d, int c, int nb, int sizeL, int sizeR, int cut, double xi) {
        double[] pos = store.positions(d);
        int[] code = store.codes(d), meta = store.eventMeta(d);
        int at = store.metaAt(c);
        int total = 0;
        for (int a = 0; a < k; a++) {
            int m = meta[at + 2 + 2 * a] - meta[at + 1 + 2 * a];
            total += Math.min(m + 2 * nb, 2 * sizeL) + Math.min(m + 2 * nb, 2 * sizeR) + 2;
        }
        store.reserveEvents(d + 1, total);
        double[] outPos = store.positions(d + 1);
        int[] outCode = store.codes(d + 1);
        int[] below = store.eventMeta(d + 1);
        int atL = store.metaAt(0), atR = store.metaAt(1);
        below[atL] = sizeL;
        below[atR] = sizeR;
        int startL = 0, startR = 0;
        for (int a = 0; a < k; a++) startR += Math.min(meta[at + 2 + 2 * a] - meta[at + 1 + 2 * a] + 2 * nb, 2 * sizeL) + 1;
        for (int a = 0; a < k; a++) {
            int from = meta[at + 1 + 2 * a], to = meta[at + 2 + 2 * a], endL, endR;
            if (a == cut) {
                long ends = copyAtThePlane(pos, code, from, to, xi, nb, outPos, outCode, startL, startR);
                endL = (int) (ends >>> 32);
                endR = (int) ends;
            } else {
                long ends = copyOneSided(pos, code, from, to, outPos, outCode, startL, startR);
                endL = cut < 0 ? mergeStraddlers(0, a, nb, outPos, outCode, startL, (int) (ends >>> 32)) : (int) (ends >>> 32);
                endR = cut < 0 ? mergeStraddlers(1, a, nb, outPos, outCode, startR, (int) ends) : (int) ends;
            }
            below[atL + 1 + 2 * a] = startL;
            below[atL + 2 + 2 * a] = endL;
            below[atR + 1 + 2 * a] = startR;
            below[atR + 2 + 2 * a] = endR;
            startL += Math.min(to - from + 2 * nb, 2 * sizeL) + 1;
            startR += Math.min(to - from + 2 * nb, 2 * sizeR) + 1;
        }
    }

    /**
     * The split axis, uncut: the right child's events start with a start at the plane for each
     * straddler, then each event is copied to its side, a straddler's start to the left only and
     * its end to the right only; the left child's end with an end at the plane for each straddler.
     * Returns both ends, as {@code endL << 32 | endR}.
     */
    private long copyAtThePlane(double[] pos, int[] code, int from, int to, double xi, int nb, double[] outPos, int[] outCode,
                                int atL, int atR) {
        int endL = atL, endR = atR;
        for (int i = 0; i < nb; i++) {
            outPos[endR] = xi;
            outCode[endR++] = EventCode.of(EventCode.START, straddlers[i]);
        }
        for (int e = from; e < to; e++) {
            int cd = code[e], s = side[EventCode.primitive(cd)];
            if (s == BOTH) s = EventCode.kind(cd) == EventCode.START ? LEFT : RIGHT;
            if ((s & LEFT) != 0) { outPos[endL] = pos[e]; outCode[endL++] = cd; }
            if ((s & RIGHT) != 0) { outPos[endR] = pos[e]; outCode[endR++] = cd; }
        }
        for (int i = 0; i < nb; i++) {
            outPos[endL] = xi;
            outCode[endL++] = EventCode.of(EventCode.END, straddlers[i]);
        }
        return (long) endL << 32 | endR;
    }

    /**
     * Copies the events {@code [from, to)} in order to the left region from {@code atL} and the
     * right one from {@code atR}, each where its primitive's side sends it (a straddler's to
     * neither, or, marked {@link #BOTH}, to both). Branch-free: every event is written to both regions and kept where its side bit
     * says. Returns both ends, as {@code endL << 32 | endR}.
     */
    private long copyOneSided(double[] pos, int[] code, int from, int to, double[] outPos, int[] outCode, int atL, int atR) {
        int endL = atL, endR = atR;
        byte[] side = this.side;
        for (int e = from; e < to; e++) {
            int c = code[e], s = side[EventCode.primitive(c)];
            double x = pos[e];
            outPos[endL] = x;
            outCode[endL] = c;
            endL += s & 1;
            outPos[endR] = x;
            outCode[endR] = c;
            endR += s >>> 1;
        }
        return (long) endL << 32 | endR;
    }

    /**
     * Sorts the events on {@code axis} of the straddlers that reach one child (0 left, 1 right)
     * and merges them into that child's sorted events {@code [from, end)}; returns the new end.
     */
    private int mergeStraddlers(int child, int axis, int nb, double[] outPos, int[] outCode, int from, int end) {
        if (nb == 0) return end;
        if (extraPos.length < 2 * nb) {
            extraPos = new double[NodeStore.grown(extraPos.length, 2 * nb)];
            extraCode = new int[extraPos.length];
        }
        int m = 0;
        for (int i = 0; i < nb; i++)
            if ((goesTo[i] & (1 << child)) != 0)
                m = EventRoot.addEvents(bounds, k, child * nb + i, straddlers[i], axis, extraPos, extraCode, m);
        store.sort.sort(extraPos, extraCode, 0, m);
        mergeBackward(outPos, outCode, from, end, extraPos, extraCode, m);
        return end + m;
    }

    /** Merges the sorted {@code sp[0..m)} into the sorted {@code dp[from..end)}, which has room after it: from the back. */
    private static void mergeBackward(double[] dp, int[] dc, int from, int end, double[] sp, int[] sc, int m) {
        int i = end - 1, s = m - 1, at = end + m - 1;
        while (s >= 0) {
            if (i >= from && dp[i] > sp[s]) { dp[at] = dp[i]; dc[at--] = dc[i--]; }
            else { dp[at] = sp[s]; dc[at--] = sc[s--]; }
        }
    }
}
