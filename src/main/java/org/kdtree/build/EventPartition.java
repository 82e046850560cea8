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
    private static final byte LEFT = 0, RIGHT = 1, BOTH = 2;
    private static final double[] NO_POS = {};
    private static final int[] NO_CODE = {};

    private EventPartition() {
    }

    static Children split(Primitives prims, EventNode node, SplitPlane p, boolean perfect) {
        int k = node.dimension(), n = node.size(), axis = p.axis();
        double xi = p.position();
        boolean planarLeft = p.planarLeft();
        double[] src = node.clippedBounds();
        int[] refs = node.refs();
        // Per reference: first its side (bit 0: left only, bit 1: right only, neither: both), then
        // also its index in its child, as index << 2 | side, for renumbering its events.
        int[] index = new int[n];
        int[] countL = new int[k + 1], countR = new int[k + 1];
        int nl = 0, nr = 0, nb = 0;
        for (int j = 0, o = 0; j < n; j++, o += 2 * k) {
            double lo = src[o + axis], hi = src[o + k + axis];
            byte s;
            if (lo == xi && hi == xi) s = planarLeft ? LEFT : RIGHT;
            else if (hi <= xi) s = LEFT;
            else if (lo >= xi) s = RIGHT;
            else s = BOTH;
            index[j] = s == LEFT ? 1 : s == RIGHT ? 2 : 0;
            if (s == LEFT) { nl++; addCounts(src, o, k, countL); }
            else if (s == RIGHT) { nr++; addCounts(src, o, k, countR); }
            else { nl++; nr++; nb++; }
        }
        Box lv = node.voxel().lowerPart(axis, xi), rv = node.voxel().upperPart(axis, xi);
        int[] lr = new int[nl], rr = new int[nr];
        double[] lc = new double[2 * k * nl], rc = new double[2 * k * nr];
        int[] straddleL = nb > 0 ? new int[nb] : NO_CODE, straddleR = nb > 0 ? new int[nb] : NO_CODE;
        Box tmp = nb > 0 ? new Box(k) : null;
        int il = 0, ir = 0, bl = 0, br = 0;
        for (int j = 0; j < n; j++) {
            int prim = refs[j];
            switch (index[j]) {
                case 1 -> { index[j] = il << 2 | 1; lr[il] = prim; System.arraycopy(src, 2 * k * j, lc, 2 * k * il++, 2 * k); }
                case 2 -> { index[j] = ir << 2 | 2; rr[ir] = prim; System.arraycopy(src, 2 * k * j, rc, 2 * k * ir++, 2 * k); }
                default -> {
                    // As in Partition: a straddler whose exact clip misses a child (it only reached
                    // the plane through padding) does not go to that child.
                    if (Partition.childBounds(prims, prim, src, j, lv, perfect, tmp, lc, il)) {
                        straddleL[bl++] = il;
                        lr[il] = prim;
                        addCounts(lc, 2 * k * il++, k, countL);
                    }
                    if (Partition.childBounds(prims, prim, src, j, rv, perfect, tmp, rc, ir)) {
                        straddleR[br++] = ir;
                        rr[ir] = prim;
                        addCounts(rc, 2 * k * ir++, k, countR);
                    }
                }
            }
        }
        if (il < nl) { lr = java.util.Arrays.copyOf(lr, il); lc = java.util.Arrays.copyOf(lc, 2 * k * il); }
        if (ir < nr) { rr = java.util.Arrays.copyOf(rr, ir); rc = java.util.Arrays.copyOf(rc, 2 * k * ir); }
        int[] startL = prefix(countL, k), startR = prefix(countR, k);
        // One slot of slack at the end: the branch-free copy writes every event to both sides.
        double[] lp = new double[startL[k] + 1], rp = new double[startR[k] + 1];
        int[] lcode = new int[startL[k] + 1], rcode = new int[startR[k] + 1];
        double[] sp = nb > 0 ? new double[2 * nb] : NO_POS;
        int[] sc = nb > 0 ? new int[2 * nb] : NO_CODE;
        double[] pos = node.positions();
        int[] code = node.codes();
        for (int a = 0; a < k; a++) {
            int atL = startL[a], atR = startR[a];
            for (int e = node.axisStart(a), end = node.axisStart(a + 1); e < end; e++) {
                int c = code[e];
                int t = index[c >>> 2];
                int bits = t & 3;
                double x = pos[e];
                int renumbered = (t & ~3) | (c & 3);
                lp[atL] = x;
                lcode[atL] = renumbered;
                atL += bits & 1;
                rp[atR] = x;
                rcode[atR] = renumbered;
                atR += bits >>> 1;
            }
            if (nb > 0) {
                int ml = straddlerEvents(lc, k, straddleL, bl, a, sp, sc);
                mergeBackward(lp, lcode, startL[a], atL, sp, sc, ml);
                int mr = straddlerEvents(rc, k, straddleR, br, a, sp, sc);
                mergeBackward(rp, rcode, startR[a], atR, sp, sc, mr);
            }
        }
        return new Children(new EventNode(lv, lr, lc, node.depth() + 1, lp, lcode, startL),
                new EventNode(rv, rr, rc, node.depth() + 1, rp, rcode, startR));
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

    /** Adds the event counts per axis of the reference whose bounds start at {@code o}. */
    private static void addCounts(double[] clipped, int o, int k, int[] count) {
        for (int a = 0; a < k; a++) count[a] += clipped[o + a] == clipped[o + k + a] ? 1 : 2;
    }

    /** Turns per-axis counts {@code c[0..k)} into start offsets {@code [0, c0, c0+c1, ...]}, in place. */
    private static int[] prefix(int[] c, int k) {
        int sum = 0;
        for (int a = 0; a <= k; a++) {
            int v = a < k ? c[a] : 0;
            c[a] = sum;
            sum += v;
        }
        return c;
    }

    /** The sorted events on {@code axis} of the straddlers, at their child indices {@code at[0..nb)}. */
    private static int straddlerEvents(double[] childClipped, int k, int[] at, int nb, int axis, double[] sp, int[] sc) {
        int m = 0;
        for (int i = 0; i < nb; i++) m = EventNode.addEvents(childClipped, k, at[i], at[i], axis, sp, sc, m);
        EventSort.sort(sp, sc, m);
        return m;
    }
}
