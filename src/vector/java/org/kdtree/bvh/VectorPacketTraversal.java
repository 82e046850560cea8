package org.kdtree.bvh;

import jdk.incubator.vector.DoubleVector;
import jdk.incubator.vector.VectorMask;
import jdk.incubator.vector.VectorOperators;
import jdk.incubator.vector.VectorSpecies;
import org.kdtree.accel.Hit;
import org.kdtree.accel.OctantSplit;
import org.kdtree.accel.RayPacket;
import org.kdtree.accel.RayQuery;
import org.kdtree.accel.TriangleIntersector;
import org.kdtree.geom.Tolerance;

/**
 * Packets of coherent rays through a 3-D {@link Bvh}'s compact binary layout ({@link PairNodes})
 * with the Vector API, the rays in the lanes: a packet's 64 rays are 64 / lanes groups of
 * {@link DoubleVector#SPECIES_PREFERRED} (8 with AVX-512), and which rays are still in play is a
 * mask, one bit per ray, instead of {@link PacketTraversal}'s range of rays.
 * <ol>
 * <li>At each node, each child's box is first tested for the whole packet at once
 * ({@link PacketRays#packetEnters}); if some ray may enter it, each group of the node's rays tests
 * both children's slabs in its lanes, each lane exactly the single ray's test ({@link
 * PairTraversal}: the same operations in the same order, in double), giving each child the mask
 * of the rays that enter it.</li>
 * <li>The nearer child (for its first ray) is taken next, the other saved with its mask.</li>
 * <li>At a leaf, each group tests each triangle in its lanes with the watertight test
 * ({@link TriangleIntersector#test}'s operations, lane by lane, when all rays share the sheared
 * frame's axes; otherwise one ray at a time), keeping per lane the closest hit so far and, of two
 * hits equally close, the lower leaf position.</li>
 * </ol>
 * A ray enters exactly the boxes it enters alone (bar those its closest hit so far rules out),
 * and tests their triangles with the same arithmetic: each ray's hit is its single-ray hit, bit
 * for bit. An any-hit ray leaves the packet at its first hit, and the packet stops when none is
 * left; leaves whose triangles no ray's segment reaches are skipped ({@link
 * PacketRays#sidedTriangles}).
 *
 * <p>Compiled for JDK 21 with {@code jdk.incubator.vector} (src/vector/java) and loaded only
 * through {@link VectorPath}. Packets that mix direction signs go as one packet per octant
 * ({@link OctantSplit}); small ones ({@link #SMALL}), and rays with a zero direction component or
 * a negative tMin, one ray at a time. Allocation-free per packet (the vectors are scalar-replaced
 * by C2); not thread safe: one per thread.
 */
final class VectorPacketTraversal extends PacketLoop {
    private static final VectorSpecies<Double> S = DoubleVector.SPECIES_PREFERRED;
    /** Rays per vector, and the bits of one group in a packet's mask. */
    private static final int L = S.length();
    private static final long GROUP_BITS = (1L << L) - 1;
    private static final int N = RayPacket.CAPACITY;
    /**
     * Packets of at most this many rays (a quarter of one; a renderer's shadow rays from one point
     * of a reflection) are traced one ray at a time: measured on the Cornell box, 1.16 x faster so,
     * the set-up and the per-node masks costing more than the shared node reads save.
     */
    private static final int SMALL = N / 4;
    private static final double SLACK = Tolerance.TRAVERSAL_SLACK;
    private static final double SHRINK = 1 - SLACK, GROW = 1 + SLACK;
    private static final int STRIDE = PairNodes.STRIDE, RIGHT = PairNodes.RIGHT, LINKS = PairNodes.LINKS;

    /** Saved children (as {@link PairNodes#code}) with the mask of rays that enter them. */
    private final int[] stackEntry;
    private final long[] stackMask;
    /**
     * Per ray: the end of its interval so far (tMax, then its closest hit's t), its slack-widened
     * value (-infinity once an any-hit ray is blocked), the hit's leaf position (-1 for none; a
     * double, to sit in a lane) and barycentrics.
     */
    private final double[] best = new double[N], limit = new double[N], position = new double[N],
            bu = new double[N], bv = new double[N];

    VectorPacketTraversal(Bvh bvh, RayQuery single) {
        super(bvh, single, SMALL);
        if (N % L != 0 || L > 32) throw new IllegalStateException(L + " lanes do not divide a packet of " + N);
        int depth = bvh.maxDepth() + 2;
        stackEntry = new int[depth];
        stackMask = new long[depth];
    }

    @Override void trace(RayPacket p, boolean any) {
        int n = p.size();
        PacketRays q = rays;
        for (int i = 0; i < n; i++) {
            best[i] = p.tMax[i];
            limit[i] = best[i] + Math.abs(best[i]) * SLACK;
            position[i] = -1;
        }
        java.util.Arrays.fill(limit, n, N, Double.NEGATIVE_INFINITY);
        long all = n == N ? -1L : (1L << n) - 1, done = 0, unhit = all;
        double limitHi = maxLimit();
        int[] nd = words;
        int sp = 0, e = 0;
        long mask = all;
        while (true) {
            if (e >= 0) {
                int l = STRIDE * e, r = l + RIGHT, link = l + LINKS;
                long lm = q.packetEnters(nd, l, limitHi) ? enter(p, nd, l, mask, false) : 0;
                long rm = q.packetEnters(nd, r, limitHi) ? enter(p, nd, r, mask, false) : 0;
                if (lm != 0 && rm != 0) {
                    boolean rightFirst = rays.entry(p, nd, r, Long.numberOfTrailingZeros(rm)) < rays.entry(p, nd, l, Long.numberOfTrailingZeros(lm));
                    stackEntry[sp] = PairNodes.code(nd, rightFirst ? link : link + 2);
                    stackMask[sp++] = rightFirst ? lm : rm;
                    e = PairNodes.code(nd, rightFirst ? link + 2 : link);
                    mask = rightFirst ? rm : lm;
                    continue;
                }
                if ((lm | rm) != 0) {
                    e = PairNodes.code(nd, lm != 0 ? link : link + 2);
                    mask = lm | rm;
                    continue;
                }
            } else {
                int word = -1 - e;
                long in = enter(p, nd, PairNodes.boxOf(word), mask, true);
                if (in != 0) {
                    long changed = leaf(p, nd, word, in, any);
                    if (any) {
                        done |= changed;
                        if (done == all) break;
                    } else if ((unhit &= ~changed) == 0 && changed != 0) {
                        limitHi = maxLimit();   // the packet's largest limit falls only once every ray has a hit
                    }
                }
            }
            mask = 0;
            while (mask == 0 && sp > 0) mask = stackMask[--sp] & ~done;
            if (mask == 0) break;
            e = stackEntry[sp];
        }
        for (int i = 0; i < n; i++) {
            int at = (int) position[i];
            if (at < 0) {
                p.primitive[i] = -1;
                p.t[i] = Double.POSITIVE_INFINITY;
                p.u[i] = p.v[i] = 0;
            } else {
                p.primitive[i] = prim[at];
                p.t[i] = best[i];
                p.u[i] = bu[i];
                p.v[i] = bv[i];
            }
        }
    }

    /**
     * The largest limit of a ray of the packet (none NaN; those past its size are -infinity), by
     * compares: a vector carried through a loop is not of a type C2 knows, so its {@code
     * reduceLanes} stays a call with the vector boxed (measured: 33 bytes allocated per ray).
     */
    private double maxLimit() {
        double m = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < N; i++) m = limit[i] > m ? limit[i] : m;
        return m;
    }

    /**
     * The rays of {@code mask} that may enter the box at {@code b}. For a node's child ({@code
     * everyGroup} false): from the first group (of {@link #L} rays) with a ray that enters it to
     * the last, each of those two groups' lanes tested ({@link #groupSlabs}), the groups between
     * them kept whole, untested (Overbeck's ranged traversal, a group for a ray): a superset of
     * the rays that enter, never fewer. For a leaf's box ({@code everyGroup}), before its
     * triangles: every group's lanes tested.
     */
    private long enter(RayPacket p, int[] nd, int b, long mask, boolean everyGroup) {
        PacketRays q = rays;
        pnx = Float.intBitsToFloat(nd[b + q.nx]);
        pfx = Float.intBitsToFloat(nd[b + q.fx]);
        pny = Float.intBitsToFloat(nd[b + q.ny]);
        pfy = Float.intBitsToFloat(nd[b + q.fy]);
        pnz = Float.intBitsToFloat(nd[b + q.nz]);
        pfz = Float.intBitsToFloat(nd[b + q.fz]);
        if (q.sharedOrigin) {
            // plane - o: one number for every ray, the same a single ray computes.
            double ox = p.ox[0], oy = p.oy[0], oz = p.oz[0];
            pnx -= ox; pfx -= ox; pny -= oy; pfy -= oy; pnz -= oz; pfz -= oz;
        }
        long out = 0;
        if (everyGroup) {
            for (int at = 0; at < N; at += L) {
                long bits = (mask >>> at) & GROUP_BITS;
                if (bits != 0) out |= (bits & groupSlabs(p, at)) << at;
            }
            return out;
        }
        int first = -1;
        for (int at = 0; at < N; at += L) {
            long bits = (mask >>> at) & GROUP_BITS;
            if (bits == 0) continue;
            long in = bits & groupSlabs(p, at);
            if (in != 0) {
                first = at;
                out = in << at;
                break;
            }
        }
        if (first < 0) return 0;
        for (int at = N - L; at > first; at -= L) {
            long bits = (mask >>> at) & GROUP_BITS;
            if (bits == 0) continue;
            long in = bits & groupSlabs(p, at);
            if (in != 0) {
                long between = at - first > L ? mask & (-1L << (first + L)) & ((1L << at) - 1) : 0;
                return out | between | in << at;
            }
        }
        return out;
    }

    /** The near and far planes of the box {@link #enter} tests, per axis; less the origin when the rays share it. */
    private double pnx, pfx, pny, pfy, pnz, pfz;

    /**
     * The lanes of the group at {@code at} whose ray enters the box of {@link #enter}: per
     * lane, {@link WideTraversal}'s operations on its ray, {@code (plane - o) * inv}, their
     * maximum and minimum with the interval, and {@code t0 (1 - slack) <= t1 (1 + slack)}.
     */
    private long groupSlabs(RayPacket p, int at) {
        // With a shared origin the planes are already less it, and the origins read are zeros (x - 0 is x):
        // one expression either way, no vector merged from two branches (C2 would box it).
        boolean shared = rays.sharedOrigin;
        int o = shared ? 0 : at;
        DoubleVector ox = DoubleVector.fromArray(S, shared ? ZEROS : p.ox, o), oy = DoubleVector.fromArray(S, shared ? ZEROS : p.oy, o),
                oz = DoubleVector.fromArray(S, shared ? ZEROS : p.oz, o);
        DoubleVector ix = DoubleVector.fromArray(S, p.ix, at), iy = DoubleVector.fromArray(S, p.iy, at),
                iz = DoubleVector.fromArray(S, p.iz, at);
        DoubleVector t0 = DoubleVector.broadcast(S, pnx).sub(ox).mul(ix), t1 = DoubleVector.broadcast(S, pfx).sub(ox).mul(ix);
        t0 = t0.max(DoubleVector.broadcast(S, pny).sub(oy).mul(iy));
        t1 = t1.min(DoubleVector.broadcast(S, pfy).sub(oy).mul(iy));
        t0 = t0.max(DoubleVector.broadcast(S, pnz).sub(oz).mul(iz));
        t1 = t1.min(DoubleVector.broadcast(S, pfz).sub(oz).mul(iz));
        t0 = t0.max(DoubleVector.fromArray(S, rays.start, at));
        t1 = t1.min(DoubleVector.fromArray(S, limit, at));
        return t0.mul(SHRINK).compare(VectorOperators.LE, t1.mul(GROW)).toLong();
    }

    /** Zeros: the origins a group's slab test reads when the rays share theirs ({@link #enter}). */
    private static final double[] ZEROS = new double[L];

    /**
     * The rays of {@code mask} (which enter the leaf's box) test the triangles of the leaf whose
     * reference is at {@code word}: each its closest hit, or for {@code any} its first, which takes
     * it out of the packet (its limit set to -infinity, below every box). Returns the rays whose
     * answer changed.
     */
    private long leaf(RayPacket p, int[] nd, int word, long mask, boolean any) {
        int from = nd[word], end = from + nd[word + 1];
        long skip = any && rays.planeCull ? rays.sidedTriangles(corners, from, end) : 0;
        if (PacketRays.skipsAll(skip, end - from)) return 0;   // no ray can cross any of them
        rays.frame();
        if (!rays.uniformFrame) return leafOneByOne(p, from, end, mask, any);
        long changed = 0;
        for (int at = 0; at < N; at += L) {
            long bits = (mask >>> at) & GROUP_BITS;
            if (bits != 0) changed |= group(p, from, end, skip, at, bits, any) << at;
        }
        return changed;
    }

    /**
     * The lanes {@code bits} of the group at {@code at} test triangles {@code [from, end)} (bar
     * those of {@code skip}) with the watertight test, lane by lane {@link TriangleIntersector#test}'s
     * operations in its order: a hit within the ray's interval and closer than its hit so far (or as
     * close, at a lower leaf position) is recorded; for {@code any}, the lane then stops. Returns the
     * lanes that recorded a hit.
     */
    private long group(RayPacket p, int from, int end, long skip, int at, long bits, boolean any) {
        PacketRays q = rays;
        double[] c = corners;
        int kx = q.kx[0], ky = q.ky[0], kz = q.kz[0];
        // No vector is carried from one triangle to the next (C2 would box it at the loop's merge):
        // each lane's hit so far lives in the arrays, read again and written with a mask.
        long live = bits, recorded = 0;
        DoubleVector okx = DoubleVector.fromArray(S, q.okx, at), oky = DoubleVector.fromArray(S, q.oky, at),
                okz = DoubleVector.fromArray(S, q.okz, at);
        DoubleVector sx = DoubleVector.fromArray(S, q.sx, at), sy = DoubleVector.fromArray(S, q.sy, at),
                sz = DoubleVector.fromArray(S, q.sz, at);
        DoubleVector tMin = DoubleVector.fromArray(S, p.tMin, at);
        for (int r = from; r < end && live != 0; r++) {
            if (r - from < 64 && (skip & 1L << (r - from)) != 0) continue;
            int b = 9 * r;
            DoubleVector az = DoubleVector.broadcast(S, c[b + kz]).sub(okz);
            DoubleVector bz = DoubleVector.broadcast(S, c[b + 3 + kz]).sub(okz);
            DoubleVector cz = DoubleVector.broadcast(S, c[b + 6 + kz]).sub(okz);
            DoubleVector ax = DoubleVector.broadcast(S, c[b + kx]).sub(okx).sub(sx.mul(az));
            DoubleVector ay = DoubleVector.broadcast(S, c[b + ky]).sub(oky).sub(sy.mul(az));
            DoubleVector bx = DoubleVector.broadcast(S, c[b + 3 + kx]).sub(okx).sub(sx.mul(bz));
            DoubleVector by = DoubleVector.broadcast(S, c[b + 3 + ky]).sub(oky).sub(sy.mul(bz));
            DoubleVector cx = DoubleVector.broadcast(S, c[b + 6 + kx]).sub(okx).sub(sx.mul(cz));
            DoubleVector cy = DoubleVector.broadcast(S, c[b + 6 + ky]).sub(oky).sub(sy.mul(cz));
            DoubleVector u = cx.mul(by).sub(cy.mul(bx)), v = ax.mul(cy).sub(ay.mul(cx)), w = bx.mul(ay).sub(by.mul(ax));
            VectorMask<Double> outside = u.lt(0).or(v.lt(0)).or(w.lt(0)).and(u.compare(VectorOperators.GT, 0)
                    .or(v.compare(VectorOperators.GT, 0)).or(w.compare(VectorOperators.GT, 0)));
            long in = live & ~outside.toLong();
            if (in == 0) continue;
            DoubleVector det = u.add(v).add(w);
            DoubleVector t = u.mul(az).add(v.mul(bz)).add(w.mul(cz)).mul(sz).div(det);
            // As the single ray's Hit: the end of the interval so far, and no hit yet as t = +infinity (position -1).
            DoubleVector bound = DoubleVector.fromArray(S, best, at), pos = DoubleVector.fromArray(S, position, at);
            DoubleVector hitT = bound.blend(Double.POSITIVE_INFINITY, pos.lt(0));
            VectorMask<Double> ok = VectorMask.fromLong(S, in).and(det.compare(VectorOperators.NE, 0))
                    .and(t.compare(VectorOperators.GE, tMin)).and(t.compare(VectorOperators.LE, bound))
                    .and(t.lt(hitT).or(t.eq(hitT).and(pos.compare(VectorOperators.GT, r))));
            long hits = ok.toLong();
            if (hits == 0) continue;
            t.intoArray(best, at, ok);
            DoubleVector.broadcast(S, r).intoArray(position, at, ok);
            v.div(det).intoArray(bu, at, ok);
            w.div(det).intoArray(bv, at, ok);
            recorded |= hits;
            if (any) live &= ~hits;
        }
        if (recorded == 0) return 0;
        for (long m = recorded; m != 0; m &= m - 1) {
            int i = at + Long.numberOfTrailingZeros(m);
            limit[i] = any ? Double.NEGATIVE_INFINITY : best[i] + Math.abs(best[i]) * SLACK;
        }
        return recorded;
    }

    /**
     * The rays of {@code mask} (which enter the leaf's box) test the leaf's triangles, each ray
     * first to last as it would alone (an any-hit ray stops at its first hit); returns the rays
     * whose answer changed (for {@code any}: those now blocked).
     */
    private long leafOneByOne(RayPacket p, int from, int end, long mask, boolean any) {
        PacketRays q = rays;
        double[] c = corners;
        Hit h = hit;
        long changed = 0;
        for (long m = mask; m != 0; m &= m - 1) {
            int i = Long.numberOfTrailingZeros(m);
            h.primitive = (int) position[i];
            h.t = position[i] < 0 ? Double.POSITIVE_INFINITY : best[i];
            boolean found = false;
            for (int r = from; r < end && !(any && found); r++)
                found |= TriangleIntersector.test(c, 9 * r, r, q.okx[i], q.oky[i], q.okz[i], q.kx[i], q.ky[i], q.kz[i],
                        q.sx[i], q.sy[i], q.sz[i], p.tMin[i], found ? h.t : best[i], h);
            if (found) {
                best[i] = h.t;
                position[i] = h.primitive;
                bu[i] = h.u;
                bv[i] = h.v;
                limit[i] = any ? Double.NEGATIVE_INFINITY : best[i] + Math.abs(best[i]) * SLACK;
                changed |= 1L << i;
            }
        }
        return changed;
    }

}
