package org.kdtree.bvh;

import org.kdtree.accel.Hit;
import org.kdtree.accel.OctantSplit;
import org.kdtree.accel.RayPacket;
import org.kdtree.accel.RayQuery;
import org.kdtree.accel.TriangleIntersector;
import org.kdtree.geom.Tolerance;

/**
 * Packets of coherent rays through a 3-D {@link Bvh}'s compact binary layout ({@link PairNodes}),
 * after Overbeck, Ramamoorthi and Mark's ranged traversal (2008) with an interval test for the
 * whole packet (Wald, Boulos and Shirley 2007):
 * <ol>
 * <li>At each node, a child box is first tested for the whole packet at once: the slab distances
 * of the box's near and far planes bounded over the packet's ranges of origins and inverse
 * directions. If even those bounds say no ray enters, the child is skipped for all of them.</li>
 * <li>Otherwise the rays that enter it are found from each end of the range of rays still
 * active: the child is entered with the range from the first ray that enters it to the last.</li>
 * <li>The nearer child (by its first ray's entry distance) is taken next, the other saved with
 * its range.</li>
 * <li>At a leaf, every ray of the range tests the leaf's triangles with the watertight test
 * ({@link TriangleIntersector#test}).</li>
 * </ol>
 * Every per-ray test is the single-ray traversal's, in the same arithmetic, and the whole-packet
 * bounds are taken with the same operations on the extreme values (rounding is monotonic, so a
 * bound is never inside any ray's own value): a child skipped for the packet is a child no ray
 * would have entered alone. A ray may test more triangles than alone, never fewer of those that
 * hold its closest hit, and of two hits equally close the lower leaf position wins either way
 * ({@link TriangleIntersector#test}): each ray's hit is its single-ray hit, bit for bit.
 *
 * <p>Packets take one sign per axis for all their rays and no zero direction component, with
 * {@code tMin >= 0}: a packet whose rays mix signs (a tile across an axis of the camera) goes as one
 * packet per octant ({@link OctantSplit}); rays that fit no octant, one at a time by the single-ray query. Allocation-free per packet; not thread safe: one per thread.
 */
final class PacketTraversal extends PacketLoop {
    private static final double SLACK = Tolerance.TRAVERSAL_SLACK;
    private static final double SHRINK = 1 - SLACK, GROW = 1 + SLACK;
    private static final int STRIDE = PairNodes.STRIDE, RIGHT = PairNodes.RIGHT, LINKS = PairNodes.LINKS;
    private static final int N = RayPacket.CAPACITY;

    /** Saved children (as {@link WideTraversal}'s entries) with the range of rays that enter them. */
    private final int[] stackEntry, stackFirst, stackLast;
    /** Per ray: the closest hit so far (t, leaf position, barycentrics), and its slack-widened t. */
    private final double[] best = new double[N], limit = new double[N], bu = new double[N], bv = new double[N];
    private final int[] position = new int[N];

    PacketTraversal(Bvh bvh, RayQuery single) {
        super(bvh, single, 0);
        int depth = bvh.maxDepth() + 2;
        stackEntry = new int[depth];
        stackFirst = new int[depth];
        stackLast = new int[depth];
    }

    /**
     * Traces a coherent packet: each ray's closest hit, or (for {@code any}) whether it hits
     * anything. An any-hit ray leaves the packet at its first hit (its limit set below every box's
     * entry), as a single ray stops, and the packet stops when no ray is left.
     */
    @Override void trace(RayPacket p, boolean any) {
        int n = p.size(), active = n;
        PacketRays q = rays;
        for (int i = 0; i < n; i++) {
            best[i] = p.tMax[i];
            limit[i] = best[i] + Math.abs(best[i]) * SLACK;
            position[i] = -1;
        }
        int nx = q.nx, ny = q.ny, nz = q.nz, fx = q.fx, fy = q.fy, fz = q.fz;
        double limitHi = maxLimit(n);

        int[] nd = words;
        int sp = 0, e = 0, first = 0, last = n;
        while (true) {
            if (e >= 0) {
                int l = STRIDE * e, r = l + RIGHT, link = l + LINKS;
                // The whole packet's test of each child, then its range of rays.
                int lFirst = -1, lLast = -1, rFirst = -1, rLast = -1;
                if (q.packetEnters(nd, l, limitHi)) {
                    lFirst = firstEntering(p, nd, l, nx, ny, nz, fx, fy, fz, first, last);
                    if (lFirst >= 0) lLast = lastEntering(p, nd, l, nx, ny, nz, fx, fy, fz, lFirst, last);
                }
                if (q.packetEnters(nd, r, limitHi)) {
                    rFirst = firstEntering(p, nd, r, nx, ny, nz, fx, fy, fz, first, last);
                    if (rFirst >= 0) rLast = lastEntering(p, nd, r, nx, ny, nz, fx, fy, fz, rFirst, last);
                }
                if (lFirst >= 0 && rFirst >= 0) {
                    // Both: the near one (for its first ray) next, the other saved with its range.
                    boolean rightFirst = rays.entry(p, nd, r, rFirst) < rays.entry(p, nd, l, lFirst);
                    int near = rightFirst ? link + 2 : link, far = rightFirst ? link : link + 2;
                    stackEntry[sp] = PairNodes.code(nd, far);
                    stackFirst[sp] = rightFirst ? lFirst : rFirst;
                    stackLast[sp++] = rightFirst ? lLast : rLast;
                    e = PairNodes.code(nd, near);
                    first = rightFirst ? rFirst : lFirst;
                    last = rightFirst ? rLast : lLast;
                    continue;
                }
                if (lFirst >= 0 || rFirst >= 0) {
                    boolean left = lFirst >= 0;
                    e = PairNodes.code(nd, left ? link : link + 2);
                    first = left ? lFirst : rFirst;
                    last = left ? lLast : rLast;
                    continue;
                }
            } else {
                int word = -1 - e, box = PairNodes.boxOf(word);
                if (any) {
                    // A blocked ray's limit falls below every box; the packet's bound may stay above it (it is only an upper bound).
                    active -= anyLeaf(p, nd, word, box, nx, ny, nz, fx, fy, fz, first, last);
                    if (active == 0) break;
                } else {
                    leaf(p, nd, word, box, nx, ny, nz, fx, fy, fz, first, last);
                    limitHi = maxLimit(n);
                }
            }
            if (sp == 0) break;
            sp--;
            e = stackEntry[sp];
            first = stackFirst[sp];
            last = stackLast[sp];
        }
        for (int i = 0; i < n; i++) {
            if (position[i] < 0) {
                p.primitive[i] = -1;
                p.t[i] = Double.POSITIVE_INFINITY;
                p.u[i] = p.v[i] = 0;
            } else {
                p.primitive[i] = prim[position[i]];
                p.t[i] = best[i];
                p.u[i] = bu[i];
                p.v[i] = bv[i];
            }
        }
    }

    private double maxLimit(int n) {
        double m = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < n; i++) m = Math.max(m, limit[i]);
        return m;
    }

    /** Whether ray {@code i} enters the box at {@code b}: {@link WideTraversal}'s test, the same operations. */
    private boolean enters(RayPacket p, int[] nd, int b, int nx, int ny, int nz, int fx, int fy, int fz, int i) {
        double ox = p.ox[i], oy = p.oy[i], oz = p.oz[i], ix = p.ix[i], iy = p.iy[i], iz = p.iz[i];
        double t0 = (Float.intBitsToFloat(nd[b + nx]) - ox) * ix, t1 = (Float.intBitsToFloat(nd[b + fx]) - ox) * ix;
        t0 = Math.max(t0, (Float.intBitsToFloat(nd[b + ny]) - oy) * iy);
        t1 = Math.min(t1, (Float.intBitsToFloat(nd[b + fy]) - oy) * iy);
        t0 = Math.max(t0, (Float.intBitsToFloat(nd[b + nz]) - oz) * iz);
        t1 = Math.min(t1, (Float.intBitsToFloat(nd[b + fz]) - oz) * iz);
        t0 = Math.max(t0, rays.start[i]);
        t1 = Math.min(t1, limit[i]);
        return t0 * SHRINK <= t1 * GROW;
    }

    /** The first ray of {@code [first, last)} that enters the box at {@code b}, or -1. */
    private int firstEntering(RayPacket p, int[] nd, int b, int nx, int ny, int nz, int fx, int fy, int fz, int first, int last) {
        for (int i = first; i < last; i++) if (enters(p, nd, b, nx, ny, nz, fx, fy, fz, i)) return i;
        return -1;
    }

    /** One past the last ray of {@code [from, last)} that enters the box at {@code b} (ray {@code from} does). */
    private int lastEntering(RayPacket p, int[] nd, int b, int nx, int ny, int nz, int fx, int fy, int fz, int from, int last) {
        for (int i = last - 1; i > from; i--) if (enters(p, nd, b, nx, ny, nz, fx, fy, fz, i)) return i + 1;
        return from + 1;
    }

    /**
     * Every ray of {@code [first, last)} not yet blocked that enters the leaf's box (at {@code box}) tests its triangles (the leaf whose
     * reference is at {@code word}) as {@link WideTraversal}'s any-hit ray does, stopping at its
     * first hit, which takes it out of the packet. Returns how many rays it took out.
     */
    private int anyLeaf(RayPacket p, int[] nd, int word, int box, int nx, int ny, int nz, int fx, int fy, int fz, int first, int last) {
        double[] c = corners;
        PacketRays q = rays;
        q.frame();
        Hit h = hit;
        int from = nd[word], end = from + nd[word + 1], blocked = 0;
        long skip = rays.planeCull ? rays.sidedTriangles(c, from, end) : 0;
        if (PacketRays.skipsAll(skip, end - from)) return 0;   // no ray can cross any of them
        for (int i = first; i < last; i++) {
            if (position[i] >= 0 || !enters(p, nd, box, nx, ny, nz, fx, fy, fz, i)) continue;
            h.primitive = -1;
            h.t = Double.POSITIVE_INFINITY;
            for (int r = from; r < end; r++)
                if ((r - from >= 64 || (skip & 1L << (r - from)) == 0) && TriangleIntersector.test(c, 9 * r, r, q.okx[i], q.oky[i], q.okz[i], q.kx[i], q.ky[i], q.kz[i], q.sx[i], q.sy[i], q.sz[i],
                        p.tMin[i], best[i], h)) {
                    position[i] = r;
                    best[i] = h.t;
                    bu[i] = h.u;
                    bv[i] = h.v;
                    limit[i] = Double.NEGATIVE_INFINITY;
                    blocked++;
                    break;
                }
        }
        return blocked;
    }

    /**
     * Every ray of {@code [first, last)} that enters the leaf's box (at {@code box}: the range's
     * middle rays were not tested at its parent) tests the leaf's triangles (the leaf whose
     * reference is at {@code word}).
     */
    private void leaf(RayPacket p, int[] nd, int word, int box, int nx, int ny, int nz, int fx, int fy, int fz, int first, int last) {
        double[] c = corners;
        PacketRays q = rays;
        q.frame();
        Hit h = hit;
        int from = nd[word], end = from + nd[word + 1];
        for (int i = first; i < last; i++) {
            if (!enters(p, nd, box, nx, ny, nz, fx, fy, fz, i)) continue;   // a ray of the range that misses the leaf's box
            // As the single ray: the hit so far (none: +infinity), and t up to the closest so far (at first tMax).
            h.primitive = position[i];
            h.t = position[i] < 0 ? Double.POSITIVE_INFINITY : best[i];
            boolean found = false;
            for (int r = from; r < end; r++)
                found |= TriangleIntersector.test(c, 9 * r, r, q.okx[i], q.oky[i], q.okz[i], q.kx[i], q.ky[i], q.kz[i], q.sx[i], q.sy[i], q.sz[i],
                        p.tMin[i], found ? h.t : best[i], h);
            if (found) {
                best[i] = h.t;
                position[i] = h.primitive;
                bu[i] = h.u;
                bv[i] = h.v;
                limit[i] = best[i] + Math.abs(best[i]) * SLACK;
            }
        }
    }
}
