package org.kdtree.build;

import org.kdtree.geom.Box;
import org.kdtree.geom.SplitPlane;
import org.kdtree.shape.Primitives;

/**
 * The split step of the O(N log N) build (Wald and Havran 2006, section 4.3): classify the
 * references as left-only, right-only or both; the events of one-sided references stay
 * sorted and are copied in order (renumbered); only the straddlers are clipped to the child
 * voxels, their new events sorted and merged in. Linear in the node's events plus
 * {@code s log s} for {@code s} straddlers.
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
        double[] src = node.clippedBounds();
        byte[] side = new byte[n];
        int nl = 0, nr = 0, nb = 0;
        for (int j = 0; j < n; j++) {
            double lo = src[2 * k * j + axis], hi = src[2 * k * j + k + axis];
            byte s;
            if (lo == xi && hi == xi) s = p.planarLeft() ? LEFT : RIGHT;
            else if (hi <= xi) s = LEFT;
            else if (lo >= xi) s = RIGHT;
            else s = BOTH;
            side[j] = s;
            if (s != RIGHT) nl++;
            if (s != LEFT) nr++;
            if (s == BOTH) nb++;
        }
        Box lv = node.voxel().lowerPart(axis, xi), rv = node.voxel().upperPart(axis, xi);
        int[] lr = new int[nl], rr = new int[nr];
        double[] lc = new double[2 * k * nl], rc = new double[2 * k * nr];
        int[] index = new int[n];          // the reference's index in its child (the left one for straddlers)
        int[] straddleL = new int[nb], straddleR = new int[nb];
        Box tmp = new Box(k);
        int il = 0, ir = 0, ib = 0;
        int[] refs = node.refs();
        for (int j = 0; j < n; j++) {
            int prim = refs[j];
            switch (side[j]) {
                case LEFT -> { index[j] = il; lr[il] = prim; System.arraycopy(src, 2 * k * j, lc, 2 * k * il++, 2 * k); }
                case RIGHT -> { index[j] = ir; rr[ir] = prim; System.arraycopy(src, 2 * k * j, rc, 2 * k * ir++, 2 * k); }
                default -> {
                    straddleL[ib] = il;
                    straddleR[ib++] = ir;
                    lr[il] = prim;
                    Partition.childBounds(prims, prim, src, j, lv, perfect, tmp, lc, il++);
                    rr[ir] = prim;
                    Partition.childBounds(prims, prim, src, j, rv, perfect, tmp, rc, ir++);
                }
            }
        }
        double[][] lp = new double[k][], rp = new double[k][];
        int[][] lcode = new int[k][], rcode = new int[k][];
        double[] sp = new double[2 * nb];
        int[] sc = new int[2 * nb];
        for (int a = 0; a < k; a++) {
            double[] pos = node.positions(a);
            int[] code = node.codes(a);
            int keptL = 0, keptR = 0;
            for (int e = 0; e < code.length; e++) {
                byte s = side[code[e] >>> 2];
                if (s == LEFT) keptL++;
                else if (s == RIGHT) keptR++;
            }
            int ms = straddlerEvents(lc, k, straddleL, nb, a, sp, sc);
            lp[a] = new double[keptL + ms];
            lcode[a] = new int[keptL + ms];
            mergeSide(pos, code, side, index, LEFT, sp, sc, ms, lp[a], lcode[a]);
            ms = straddlerEvents(rc, k, straddleR, nb, a, sp, sc);
            rp[a] = new double[keptR + ms];
            rcode[a] = new int[keptR + ms];
            mergeSide(pos, code, side, index, RIGHT, sp, sc, ms, rp[a], rcode[a]);
        }
        return new Children(new EventNode(lv, lr, lc, node.depth() + 1, lp, lcode),
                new EventNode(rv, rr, rc, node.depth() + 1, rp, rcode));
    }

    /** The sorted events on {@code axis} of the straddlers, at their child indices {@code at[0..nb)}. */
    private static int straddlerEvents(double[] childClipped, int k, int[] at, int nb, int axis, double[] sp, int[] sc) {
        int m = 0;
        for (int i = 0; i < nb; i++) m = EventNode.addEvents(childClipped, k, at[i], at[i], axis, sp, sc, m);
        EventSort.sort(sp, sc, m);
        return m;
    }

    /**
     * Writes the parent's events of the references on {@code want}'s side (still in order,
     * renumbered to the child) merged with the straddlers' sorted new events.
     */
    private static void mergeSide(double[] pos, int[] code, byte[] side, int[] index, byte want,
                                  double[] sp, int[] sc, int ms, double[] dp, int[] dc) {
        int at = 0, is = 0, m = code.length;
        for (int e = 0; e < m; e++) {
            int c = code[e];
            int j = c >>> 2;
            if (side[j] != want) continue;
            double x = pos[e];
            while (is < ms && sp[is] < x) { dp[at] = sp[is]; dc[at++] = sc[is++]; }
            dp[at] = x;
            dc[at++] = index[j] << 2 | (c & 3);
        }
        while (is < ms) { dp[at] = sp[is]; dc[at++] = sc[is++]; }
    }
}
