package org.kdtree.build;

import org.kdtree.geom.Box;
import org.kdtree.geom.SplitPlane;
import org.kdtree.shape.Primitives;

/**
 * The split step of the O(N log N) build (Wald and Havran 2006, section 4.3): classify the
 * references as left-only, right-only or both; the events of one-sided references stay
 * sorted and are copied in order (renumbered) in one pass per axis; only the straddlers are
 * clipped to the child voxels, their new events sorted and merged in. Linear in the node's
 * events plus {@code s log s} for {@code s} straddlers.
 *
 * <p>References and clipped bounds come out in the same order and with the same values as
 * {@link Partition#split}, so the event build makes the very tree the other searches make.
 */
final class EventPartition {
    /** Side bits of a reference: left only, right only; a straddler has neither. */
    private static final int LEFT = 1, RIGHT = 2, BOTH = 0;

    private EventPartition() {
    }

    /**
     * Splits {@code node} by {@code p}. Both children are written into the arena level below the
     * node: references first the left child's, then the right's; events in one region per child
     * and axis, sized by {@link #region} so that nothing needs counting before it is copied.
     */
    static Children split(Primitives prims, EventNode node, SplitPlane p, boolean perfect) {
        int k = node.dimension(), n = node.size();
        EventArena arena = node.arena();
        int[] side = arena.index(n);
        classify(node, p, side);
        int nl = 0, nr = 0;
        for (int j = 0; j < n; j++) { nl += side[j] & LEFT; nr += side[j] >>> 1; }
        int nb = n - nl - nr;
        int[] straddle = clipStraddlers(prims, node, p, perfect, side, nb);
        int leftCap = nl + nb, leftRegions = 0, rightRegions = 0;
        for (int a = 0; a < k; a++) {
            leftRegions += region(node, a, nb, nl);
            rightRegions += region(node, a, nb, nr);
        }
        EventArena.Level out = arena.level(node.depth() + 1, leftCap + nr + nb, leftRegions + rightRegions);
        long counts = writeReferences(node, side, straddle, nb, out.refs, leftCap);
        int[] rangeL = new int[2 * k], rangeR = new int[2 * k];
        for (int a = 0, atL = 0, atR = leftRegions; a < k; a++) {
            splitEvents(node, a, side, straddle, nb, out, atL, atR, rangeL, rangeR);
            atL += region(node, a, nb, nl);
            atR += region(node, a, nb, nr);
        }
        int depth = node.depth() + 1, il = (int) (counts >>> 32), ir = (int) counts;
        Box lv = node.voxel().lowerPart(p.axis(), p.position()), rv = node.voxel().upperPart(p.axis(), p.position());
        return new Children(
                new EventNode(lv, out.refs, 0, il, depth, out.pos, out.code, rangeL, arena),
                new EventNode(rv, out.refs, leftCap, ir, depth, out.pos, out.code, rangeR, arena));
    }

    /**
     * Clips the {@code nb} straddlers to both children. Returns the arena's straddler table: slot
     * i is the i-th straddler in node order; {@code straddle[i]} is its index in the node, and
     * {@code straddle[nb + i]}, {@code straddle[2 nb + i]} are 0 if it goes to the left, the right
     * child, -1 if its clip misses that child. Its bounds in the children are in the arena's
     * straddler bounds, slots {@code i} (left) and {@code nb + i} (right).
     */
    private static int[] clipStraddlers(Primitives prims, EventNode node, SplitPlane p, boolean perfect, int[] side, int nb) {
        EventArena arena = node.arena();
        int[] straddle = arena.straddlers(3 * nb);
        for (int j = 0, i = 0; i < nb; j++) if (side[j] == BOTH) straddle[i++] = j;
        double[] bounds = arena.straddlerBounds(3 * nb);   // left child's, right child's, parent's
        if (!perfect) parentBoundsOfStraddlers(node, side, straddle, nb, bounds, 2 * nb);
        int[] refs = node.refArray();
        for (int i = 0; i < nb; i++) {
            int to = Partition.straddlerBounds(prims, refs[node.base() + straddle[i]], bounds, 2 * nb + i, node.voxel(), p,
                    perfect, arena.clipLeft, arena.clipRight, bounds, i, bounds, nb + i);
            straddle[nb + i] = (to & 1) != 0 ? 0 : -1;
            straddle[2 * nb + i] = (to & 2) != 0 ? 0 : -1;
        }
        return straddle;
    }

    /**
     * Writes the children's references in node order (the left child's from 0, the right's from
     * {@code leftCap}); {@code side[j]} becomes (index in its child) {@code << 2 |} side bits, and a
     * straddler's table entries its indices in the children. Returns the children's sizes as
     * {@code left << 32 | right}.
     */
    private static long writeReferences(EventNode node, int[] side, int[] straddle, int nb, int[] childRefs, int leftCap) {
        int[] refs = node.refArray();
        int base = node.base(), il = 0, ir = 0;
        for (int j = 0, i = 0; j < node.size(); j++) {
            int prim = refs[base + j], s = side[j];
            if (s == LEFT) {
                side[j] = il << 2 | LEFT;
                childRefs[il++] = prim;
            } else if (s == RIGHT) {
                side[j] = ir << 2 | RIGHT;
                childRefs[leftCap + ir++] = prim;
            } else {
                if (straddle[nb + i] == 0) { straddle[nb + i] = il; childRefs[il++] = prim; }
                if (straddle[2 * nb + i] == 0) { straddle[2 * nb + i] = ir; childRefs[leftCap + ir++] = prim; }
                i++;
            }
        }
        return (long) il << 32 | ir;
    }

    /**
     * The events of one axis for both children: the one-sided references' copied in order into
     * the regions at {@code atL} and {@code atR}, the straddlers' sorted and merged in; records
     * where each child's events of this axis begin and end.
     */
    private static void splitEvents(EventNode node, int a, int[] side, int[] straddle, int nb,
                                    EventArena.Level out, int atL, int atR, int[] rangeL, int[] rangeR) {
        EventArena arena = node.arena();
        double[] bounds = arena.straddlerBounds(3 * nb);
        int k = node.dimension();
        long ends = copyOneSided(node.positions(), node.codes(), node.eventsFrom(a), node.eventsTo(a), side,
                out.pos, out.code, atL, atR);
        int endL = (int) (ends >>> 32), endR = (int) ends;
        endL = mergeStraddlers(arena, bounds, k, straddle, nb, 0, a, out.pos, out.code, atL, endL);
        endR = mergeStraddlers(arena, bounds, k, straddle, nb, 1, a, out.pos, out.code, atR, endR);
        rangeL[2 * a] = atL;
        rangeL[2 * a + 1] = endL;
        rangeR[2 * a] = atR;
        rangeR[2 * a + 1] = endR;
    }

    /**
     * Room for one child's events on {@code axis}: its one-sided references' events are among the
     * node's, and each of its {@code oneSided + nb} references has at most two. One slot more for
     * the branch-free copy, which writes one event past the end of each region.
     */
    private static int region(EventNode node, int axis, int nb, int oneSided) {
        return Math.min(node.eventsTo(axis) - node.eventsFrom(axis) + 2 * nb, 2 * (oneSided + nb)) + 1;
    }

    /**
     * The side of each reference, from the events on the split axis (they are its clipped bounds
     * there): the same decision as {@link Partition#classify}. A start at or after the plane means
     * right only, an end at or before it left only; a planar event goes by its position, and to
     * the chosen side when it lies in the plane; a reference with neither straddles.
     */
    private static void classify(EventNode node, SplitPlane p, int[] side) {
        int axis = p.axis();
        double xi = p.position();
        int planar = p.planarLeft() ? LEFT : RIGHT;
        java.util.Arrays.fill(side, 0, node.size(), BOTH);
        double[] pos = node.positions();
        int[] code = node.codes();
        for (int e = node.eventsFrom(axis), to = node.eventsTo(axis); e < to; e++) {
            int c = code[e], kind = c & 3;
            double x = pos[e];
            if (kind == EventNode.PLANAR) side[c >>> 2] = x == xi ? planar : x < xi ? LEFT : RIGHT;
            else if (kind == EventNode.END && x <= xi) side[c >>> 2] = LEFT;
            else if (kind == EventNode.START && x >= xi) side[c >>> 2] = RIGHT;
        }
    }

    /**
     * The parent's clipped bounds of the straddlers (slot i at {@code bounds[2k (at + i)]}),
     * recovered from the events; needed only without perfect splits, where a child keeps them
     * cut by its voxel. {@link EventNode#clippedBounds} recovers them for every reference into a
     * new array; this pass writes only the straddlers' into scratch memory, which keeps that
     * variant's build at 480 ms on the bunny instead of 610.
     */
    private static void parentBoundsOfStraddlers(EventNode node, int[] side, int[] straddle, int nb, double[] bounds, int at) {
        int k = node.dimension();
        for (int i = 0; i < nb; i++) side[straddle[i]] = i << 2 | BOTH;   // slot, for the lookup below
        double[] pos = node.positions();
        int[] code = node.codes();
        for (int a = 0; a < k; a++) {
            for (int e = node.eventsFrom(a); e < node.eventsTo(a); e++) {
                int t = side[code[e] >>> 2], kind = code[e] & 3;
                if ((t & 3) != BOTH) continue;
                int o = 2 * k * (at + (t >>> 2));
                if (kind != EventNode.END) bounds[o + a] = pos[e];
                if (kind != EventNode.START) bounds[o + k + a] = pos[e];
            }
        }
        for (int i = 0; i < nb; i++) side[straddle[i]] = BOTH;
    }

    /**
     * Sorts the events on {@code axis} of the straddlers that went to one child ({@code child} 0:
     * left, bounds at slots {@code 0..nb}; 1: right, at {@code nb..2nb}) and merges them into that
     * child's sorted events {@code [from, end)}; returns the new end.
     */
    private static int mergeStraddlers(EventArena arena, double[] bounds, int k, int[] straddle, int nb, int child,
                                       int axis, double[] dp, int[] dc, int from, int end) {
        if (nb == 0) return end;
        double[] sp = arena.straddlePositions(2 * nb);
        int[] sc = arena.straddleCodes();
        int m = 0;
        for (int i = 0; i < nb; i++) {
            int index = straddle[(1 + child) * nb + i];
            if (index >= 0) m = EventNode.addEvents(bounds, k, child * nb + i, index, axis, sp, sc, m);
        }
        EventSort.sort(sp, sc, m);
        mergeBackward(dp, dc, from, end, sp, sc, m);
        return end + m;
    }

    /**
     * Copies the events {@code [from, to)} of one axis, in order, to the left region from
     * {@code atL} and the right region from {@code atR}, renumbered to the child indices in
     * {@code side}; a straddler's events go to neither. Branch-free: every event is written to
     * both regions and kept where its side bit says. Returns both ends, as {@code endL << 32 | endR}.
     */
    private static long copyOneSided(double[] pos, int[] code, int from, int to, int[] side,
                                     double[] childPos, int[] childCode, int atL, int atR) {
        int endL = atL, endR = atR;
        for (int e = from; e < to; e++) {
            int c = code[e];
            int t = side[c >>> 2];
            double x = pos[e];
            int renumbered = (t & ~3) | (c & 3);
            childPos[endL] = x;
            childCode[endL] = renumbered;
            endL += t & LEFT;
            childPos[endR] = x;
            childCode[endR] = renumbered;
            endR += (t >>> 1) & 1;
        }
        return (long) endL << 32 | endR;
    }

    /**
     * Merges the sorted {@code sp[0..m)} into the sorted {@code dp[from..to)}, which has room for
     * them right after it: from the back, so that nothing is overwritten before it is read.
     */
    private static void mergeBackward(double[] dp, int[] dc, int from, int to, double[] sp, int[] sc, int m) {
        int i = to - 1, s = m - 1, at = to + m - 1;
        while (s >= 0) {
            if (i >= from && dp[i] > sp[s]) { dp[at] = dp[i]; dc[at--] = dc[i--]; }
            else { dp[at] = sp[s]; dc[at--] = sc[s--]; }
        }
    }
}
