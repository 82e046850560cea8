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
     * and axis, sized for the parent's events of that axis plus two per straddler, so that
     * nothing needs counting before it is copied.
     */
    static Children split(Primitives prims, EventNode node, SplitPlane p, boolean perfect) {
        int k = node.dimension(), n = node.size();
        EventArena arena = node.arena();
        int[] side = arena.index(n);
        classify(node, p, side);
        int nl = 0, nr = 0;
        for (int j = 0; j < n; j++) { nl += side[j] & LEFT; nr += side[j] >>> 1; }
        int nb = n - nl - nr;

        // The straddlers: slot i is the i-th in node order; straddle[i] = its index j in the node,
        // then its index in the left child and in the right one (-1 if its clip misses that child).
        int[] straddle = arena.straddlers(3 * nb);
        for (int j = 0, i = 0; i < nb; j++) if (side[j] == BOTH) straddle[i++] = j;
        double[] bounds = arena.straddlerBounds(3 * nb);   // left child's, right child's, parent's
        if (!perfect) straddlerBounds(node, side, straddle, nb, bounds, 2 * nb);
        int[] refs = node.refArray();
        int base = node.base();
        for (int i = 0; i < nb; i++) {
            int to = Partition.straddlerBounds(prims, refs[base + straddle[i]], bounds, 2 * nb + i, node.voxel(), p, perfect,
                    arena.clipLeft, arena.clipRight, bounds, i, bounds, nb + i);
            straddle[nb + i] = (to & 1) != 0 ? 0 : -1;
            straddle[2 * nb + i] = (to & 2) != 0 ? 0 : -1;
        }

        // References, in node order; side[j] becomes (index in its child) << 2 | side bits.
        int leftCap = nl + nb, leftRegions = 0, rightRegions = 0;
        for (int a = 0; a < k; a++) {
            leftRegions += region(node, a, nb, nl);
            rightRegions += region(node, a, nb, nr);
        }
        EventArena.Level out = arena.level(node.depth() + 1, leftCap + nr + nb, leftRegions + rightRegions);
        int[] childRefs = out.refs;
        int il = 0, ir = leftCap;
        for (int j = 0, i = 0; j < n; j++) {
            int prim = refs[base + j], s = side[j];
            if (s == LEFT) {
                side[j] = il << 2 | LEFT;
                childRefs[il++] = prim;
            } else if (s == RIGHT) {
                side[j] = (ir - leftCap) << 2 | RIGHT;
                childRefs[ir++] = prim;
            } else {
                if (straddle[nb + i] == 0) { straddle[nb + i] = il; childRefs[il++] = prim; }
                if (straddle[2 * nb + i] == 0) { straddle[2 * nb + i] = ir - leftCap; childRefs[ir++] = prim; }
                i++;
            }
        }

        // Events, axis by axis: one-sided ones copied in order, the straddlers' sorted and merged in.
        double[] pos = node.positions(), childPos = out.pos;
        int[] code = node.codes(), childCode = out.code;
        int[] rangeL = new int[2 * k], rangeR = new int[2 * k];
        for (int a = 0, atL = 0, atR = leftRegions; a < k; a++) {
            int from = node.eventsFrom(a), to = node.eventsTo(a);
            long ends = copyOneSided(pos, code, from, to, side, childPos, childCode, atL, atR);
            int endL = (int) (ends >>> 32), endR = (int) ends;
            endL = mergeStraddlers(arena, bounds, k, straddle, nb, 0, a, childPos, childCode, atL, endL);
            endR = mergeStraddlers(arena, bounds, k, straddle, nb, 1, a, childPos, childCode, atR, endR);
            rangeL[2 * a] = atL;
            rangeL[2 * a + 1] = endL;
            rangeR[2 * a] = atR;
            rangeR[2 * a + 1] = endR;
            atL += region(node, a, nb, nl);
            atR += region(node, a, nb, nr);
        }
        int depth = node.depth() + 1;
        Box lv = node.voxel().lowerPart(p.axis(), p.position()), rv = node.voxel().upperPart(p.axis(), p.position());
        return new Children(
                new EventNode(lv, childRefs, 0, il, depth, childPos, childCode, rangeL, arena),
                new EventNode(rv, childRefs, leftCap, ir - leftCap, depth, childPos, childCode, rangeR, arena));
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
     * cut by its voxel.
     */
    private static void straddlerBounds(EventNode node, int[] side, int[] straddle, int nb, double[] bounds, int at) {
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
