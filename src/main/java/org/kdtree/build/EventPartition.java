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
     * node: references and clipped bounds first the left child's, then the right's; events in one
     * region per child and axis, sized for the parent's events of that axis plus two per
     * straddler, so that nothing needs counting before it is copied.
     */
    static Children split(Primitives prims, EventNode node, SplitPlane p, boolean perfect) {
        int k = node.dimension(), n = node.size(), base = node.base();
        EventArena arena = node.arena();
        int[] side = arena.index(n);
        int nb = classify(node, p, side);
        int nl = 0, nr = 0;
        for (int j = 0; j < n; j++) { nl += side[j] & LEFT; nr += side[j] >>> 1; }
        int leftCap = nl + nb, events = node.eventsTo(k - 1) - node.eventsFrom(0);
        int regionSlack = 2 * nb, sideEvents = events + k * regionSlack;
        EventArena.Level out = arena.level(node.depth() + 1, leftCap + nr + nb, 2 * sideEvents);
        Box lv = node.voxel().lowerPart(p.axis(), p.position()), rv = node.voxel().upperPart(p.axis(), p.position());

        // References and clipped bounds; side[j] becomes (index in its child) << 2 | side bits.
        int[] refs = node.refArray(), childRefs = out.refs, straddle = arena.straddlers(2 * nb);
        double[] src = node.clippedArray(), childClipped = out.clipped;
        int il = 0, ir = leftCap, bl = 0, br = 0, w = 2 * k;
        for (int j = 0; j < n; j++) {
            int prim = refs[base + j], s = side[j];
            if (s == LEFT) {
                side[j] = il << 2 | LEFT;
                childRefs[il] = prim;
                System.arraycopy(src, w * (base + j), childClipped, w * il++, w);
            } else if (s == RIGHT) {
                side[j] = (ir - leftCap) << 2 | RIGHT;
                childRefs[ir] = prim;
                System.arraycopy(src, w * (base + j), childClipped, w * ir++, w);
            } else {
                // As in Partition: a straddler whose exact clip misses a child (it only reached
                // the plane through padding) does not go to that child.
                if (Partition.childBounds(prims, prim, src, base + j, lv, perfect, arena.clipBox, childClipped, il)) {
                    straddle[bl++] = il;
                    childRefs[il++] = prim;
                }
                if (Partition.childBounds(prims, prim, src, base + j, rv, perfect, arena.clipBox, childClipped, ir)) {
                    straddle[nb + br++] = ir;
                    childRefs[ir++] = prim;
                }
            }
        }

        // Events, axis by axis: one-sided ones copied in order, the straddlers' sorted and merged in.
        double[] pos = node.positions(), childPos = out.pos;
        int[] code = node.codes(), childCode = out.code;
        int[] rangeL = new int[2 * k], rangeR = new int[2 * k];
        for (int a = 0, atL = 0, atR = sideEvents; a < k; a++) {
            int from = node.eventsFrom(a), to = node.eventsTo(a);
            long ends = copyOneSided(pos, code, from, to, side, childPos, childCode, atL, atR);
            int endL = (int) (ends >>> 32), endR = (int) ends;
            endL = mergeStraddlers(arena, childClipped, k, straddle, 0, bl, 0, a, childPos, childCode, atL, endL);
            endR = mergeStraddlers(arena, childClipped, k, straddle, nb, br, leftCap, a, childPos, childCode, atR, endR);
            rangeL[2 * a] = atL;
            rangeL[2 * a + 1] = endL;
            rangeR[2 * a] = atR;
            rangeR[2 * a + 1] = endR;
            int region = to - from + regionSlack;
            atL += region;
            atR += region;
        }
        int depth = node.depth() + 1;
        return new Children(
                new EventNode(lv, childRefs, childClipped, 0, il, depth, childPos, childCode, rangeL, arena),
                new EventNode(rv, childRefs, childClipped, leftCap, ir - leftCap, depth, childPos, childCode, rangeR, arena));
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

    /** Writes each reference's side bits into {@code side[j]}; returns the number of straddlers. */
    private static int classify(EventNode node, SplitPlane p, int[] side) {
        int k = node.dimension(), n = node.size(), axis = p.axis();
        double xi = p.position();
        int planar = p.planarLeft() ? LEFT : RIGHT, nb = 0;
        double[] src = node.clippedArray();
        for (int j = 0, o = 2 * k * node.base() + axis; j < n; j++, o += 2 * k) {
            double lo = src[o], hi = src[o + k];
            int s;
            if (lo == xi && hi == xi) s = planar;
            else if (hi <= xi) s = LEFT;
            else if (lo >= xi) s = RIGHT;
            else { s = BOTH; nb++; }
            side[j] = s;
        }
        return nb;
    }

    /**
     * Sorts the events on {@code axis} of the straddlers that went to one child (their level
     * indices are {@code straddle[first .. first + count)}, the child starts at {@code childBase})
     * and merges them into that child's sorted events {@code [from, end)}; returns the new end.
     */
    private static int mergeStraddlers(EventArena arena, double[] childClipped, int k, int[] straddle, int first, int count,
                                       int childBase, int axis, double[] dp, int[] dc, int from, int end) {
        if (count == 0) return end;
        double[] sp = arena.straddlePositions(2 * count);
        int[] sc = arena.straddleCodes();
        int m = 0;
        for (int i = first; i < first + count; i++)
            m = EventNode.addEvents(childClipped, k, straddle[i], straddle[i] - childBase, axis, sp, sc, m);
        EventSort.sort(sp, sc, m);
        mergeBackward(dp, dc, from, end, sp, sc, m);
        return end + m;
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
