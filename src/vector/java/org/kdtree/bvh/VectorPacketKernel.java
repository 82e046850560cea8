package org.kdtree.bvh;

import jdk.incubator.vector.DoubleVector;
import jdk.incubator.vector.VectorMask;
import jdk.incubator.vector.VectorOperators;
import jdk.incubator.vector.VectorSpecies;
import org.kdtree.accel.RayPacket;
import org.kdtree.geom.Tolerance;

/**
 * The packet loop's kernels ({@link PacketKernel}) with the Vector API: a group is as many rays
 * as the machine's double lanes ({@link DoubleVector#SPECIES_PREFERRED}: 8 with AVX-512), each
 * lane exactly the Java 17 kernel's operations on its ray, in the same order. Compiled for JDK 21
 * with {@code jdk.incubator.vector} (src/vector/java) and loaded only through
 * {@link org.kdtree.accel.Vectorization#kernel}. Allocation-free (the vectors are scalar-replaced
 * by C2: no vector is carried through a loop's merge, where C2 would box it).
 */
public final class VectorPacketKernel implements PacketKernel {
    private static final VectorSpecies<Double> S = DoubleVector.SPECIES_PREFERRED;
    private static final int L = S.length();
    /**
     * Packets of at most this many rays (a quarter of one; a renderer's shadow rays from one point
     * of a reflection) are traced one ray at a time: measured on the Cornell box, 1.16 x faster so,
     * the set-up and the per-node masks costing more than the shared node reads save.
     */
    private static final int SMALL = RayPacket.CAPACITY / 4;
    private static final double SLACK = Tolerance.TRAVERSAL_SLACK;
    private static final double SHRINK = 1 - SLACK, GROW = 1 + SLACK;
    /** Zeros: the origins a group's slab test reads when the rays share theirs ({@link #enter}). */
    private static final double[] ZEROS = new double[L];

    /** The kernels; made by {@link org.kdtree.accel.Vectorization#kernel}. */
    public VectorPacketKernel() {
    }

    @Override public int lanes() { return L; }

    @Override public int oneByOneUpTo() { return SMALL; }

    @Override public long enter(RayPacket p, PacketRays q, int at, double pnx, double pfx, double pny, double pfy, double pnz, double pfz) {
        // With a shared origin, plane - o is one number for every ray (the one a single ray computes),
        // and the origins read are zeros (x - 0 is x): one expression either way, no vector merged from two branches.
        boolean shared = q.sharedOrigin;
        if (shared) {
            double ox = p.ox[0], oy = p.oy[0], oz = p.oz[0];
            pnx -= ox; pfx -= ox; pny -= oy; pfy -= oy; pnz -= oz; pfz -= oz;
        }
        int o = shared ? 0 : at;
        DoubleVector ox = DoubleVector.fromArray(S, shared ? ZEROS : p.ox, o), oy = DoubleVector.fromArray(S, shared ? ZEROS : p.oy, o),
                oz = DoubleVector.fromArray(S, shared ? ZEROS : p.oz, o);
        DoubleVector ix = DoubleVector.fromArray(S, p.ix, at), iy = DoubleVector.fromArray(S, p.iy, at),
                iz = DoubleVector.fromArray(S, p.iz, at);
        DoubleVector t0 = DoubleVector.broadcast(S, pnx).sub(ox).mul(ix), t1 = DoubleVector.broadcast(S, pfx).sub(ox).mul(ix);
        t0 = t0.max(DoubleVector.fromArray(S, q.start, at));
        t1 = t1.min(DoubleVector.fromArray(S, q.limit, at));
        t0 = t0.max(DoubleVector.broadcast(S, pny).sub(oy).mul(iy));
        t1 = t1.min(DoubleVector.broadcast(S, pfy).sub(oy).mul(iy));
        t0 = t0.max(DoubleVector.broadcast(S, pnz).sub(oz).mul(iz));
        t1 = t1.min(DoubleVector.broadcast(S, pfz).sub(oz).mul(iz));
        return t0.mul(SHRINK).compare(VectorOperators.LE, t1.mul(GROW)).toLong();
    }

    @Override public long hit(RayPacket p, PacketRays q, double[] c, int from, int end, long skip, int at, long bits, boolean any) {
        int kx = q.kx, ky = q.ky, kz = q.kz;
        // No vector is carried from one triangle to the next (C2 would box it at the loop's merge):
        // each lane's hit so far lives in the arrays, read again and written with a mask.
        long live = bits, recorded = 0;
        double[] best = q.best, position = q.position;
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
            v.div(det).intoArray(q.bu, at, ok);
            w.div(det).intoArray(q.bv, at, ok);
            recorded |= hits;
            if (any) live &= ~hits;
        }
        return recorded;
    }
}
