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

    private EventPartition() {
    }

    static Children split(Primitives prims, EventNode node, SplitPlane p, boolean perfect) {
        int k = node.dimension(), n = node.size(), axis = p.axis();
        double xi = p.position();
        boolean planarLeft = p.planarLeft();
        double[] src = node.clippedBounds();
        int[] refs = node.refs();
        byte[] side = new byte[n];
        int[] index = new int[n];           // the reference's index in its child (the left one for straddlers)
        int[] countL = new int[k + 1], countR = new int[k + 1];
        int nl = 0, nr = 0, nb = 0;
        for (int j = 0, o = 0; j < n; j++, o += 2 * k) {
            double lo = src[o + axis], hi = src[o + k + axis];
            byte s;
            if (lo == xi && hi == xi) s = planarLeft ? LEFT : RIGHT;
            else if (hi <= xi) s = LEFT;
            else if (lo >= xi) s = RIGHT;
            else s = BOTH;
            side[j] = s;
            if (s == LEFT) { index[j] = nl++; addCounts(src, o, k, countL); }
            else if (s == RIGHT) { index[j] = nr++; addCounts(src, o, k, countR); }
            else { index[j] = nl++; nr++; nb++; }
        }
        Box lv = node.voxel().lowerPart(axis, xi), rv = node.voxel().upperPart(axis, xi);
        int[] lr = new int[nl], rr = new int[nr];
        double[] lc = new double[2 * k * nl], rc = new double[2 * k * nr];
        int[] straddleL = new int[nb], straddleR = new int[nb];
        Box tmp = nb > 0 ? new Box(k) : null;
        int il = 0, ir = 0, ib = 0;
        for (int j = 0; j < n; j++) {
            int prim = refs[j];
            switch (side[j]) {
                case LEFT -> { lr[il] = prim; System.arraycopy(src, 2 * k * j, lc, 2 * k * il++, 2 * k); }
                case RIGHT -> { rr[ir] = prim; System.arraycopy(src, 2 * k * j, rc, 2 * k * ir++, 2 * k); }
                default -> {
                    straddleL[ib] = il;
                    straddleR[ib++] = ir;
                    lr[il] = prim;
                    Partition.childBounds(prims, prim, src, j, lv, perfect, tmp, lc, il);
                    addCounts(lc, 2 * k * il++, k, countL);
                    rr[ir] = prim;
                    Partition.childBounds(prims, prim, src, j, rv, perfect, tmp, rc, ir);
                    addCounts(rc, 2 * k * ir++, k, countR);
                }
            }
        }
        int[] startL = prefix(countL, k), startR = prefix(countR, k);
        double[] lp = new double[startL[k]], rp = new double[startR[k]];
        int[] lcode = new int[startL[k]], rcode = new int[startR[k]];
        double[] slp = new double[2 * nb], srp = new double[2 * nb];
        int[] slc = new int[2 * nb], src2 = new int[2 * nb];
        double[] pos = node.positions();
        int[] code = node.codes();
        for (int a = 0; a < k; a++) {
            int ml = straddlerEvents(lc, k, straddleL, nb, a, slp, slc);
            int mr = straddlerEvents(rc, k, straddleR, nb, a, srp, src2);
            int atL = startL[a], atR = startR[a], sl = 0, sr = 0;
            for (int e = node.axisStart(a), end = node.axisStart(a + 1); e < end; e++) {
                int c = code[e];
                int j = c >>> 2;
                byte s = side[j];
                if (s == BOTH) continue;
                double x = pos[e];
                int renumbered = index[j] << 2 | (c & 3);
                if (s == LEFT) {
                    while (sl < ml && slp[sl] < x) { lp[atL] = slp[sl]; lcode[atL++] = slc[sl++]; }
                    lp[atL] = x;
                    lcode[atL++] = renumbered;
                } else {
                    while (sr < mr && srp[sr] < x) { rp[atR] = srp[sr]; rcode[atR++] = src2[sr++]; }
                    rp[atR] = x;
                    rcode[atR++] = renumbered;
                }
            }
            while (sl < ml) { lp[atL] = slp[sl]; lcode[atL++] = slc[sl++]; }
            while (sr < mr) { rp[atR] = srp[sr]; rcode[atR++] = src2[sr++]; }
        }
        return new Children(new EventNode(lv, lr, lc, node.depth() + 1, lp, lcode, startL),
                new EventNode(rv, rr, rc, node.depth() + 1, rp, rcode, startR));
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
