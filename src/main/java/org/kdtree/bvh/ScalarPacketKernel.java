package org.kdtree.bvh;

import org.kdtree.accel.Hit;
import org.kdtree.accel.RayPacket;
import org.kdtree.accel.TriangleIntersector;
import org.kdtree.geom.Tolerance;

/** The packet loop's kernels in Java 17: a group is one ray ({@link PacketKernel}). */
final class ScalarPacketKernel implements PacketKernel {
    private static final double SHRINK = 1 - Tolerance.TRAVERSAL_SLACK, GROW = 1 + Tolerance.TRAVERSAL_SLACK;
    @Override public int lanes() { return 1; }

    @Override public int oneByOneUpTo() { return 0; }

    /** {@link ScalarRayKernel#enter}'s operations on ray {@code i}'s slabs. */
    @Override public long enter(RayPacket p, PacketRays q, int i, double pnx, double pfx, double pny, double pfy, double pnz, double pfz) {
        double ox = p.ox[i], oy = p.oy[i], oz = p.oz[i], ix = p.ix[i], iy = p.iy[i], iz = p.iz[i];
        double t0 = Math.max(q.start[i], (pnx - ox) * ix), t1 = Math.min(q.limit[i], (pfx - ox) * ix);
        t0 = Math.max(t0, (pny - oy) * iy);
        t1 = Math.min(t1, (pfy - oy) * iy);
        t0 = Math.max(t0, (pnz - oz) * iz);
        t1 = Math.min(t1, (pfz - oz) * iz);
        return t0 * SHRINK <= t1 * GROW ? 1 : 0;
    }

    @Override public long hit(RayPacket p, PacketRays q, double[] c, int from, int end, long skip, int i, long bits, boolean any) {
        Hit h = q.hit;
        int at = (int) q.position[i];
        h.primitive = at;
        h.t = at < 0 ? Double.POSITIVE_INFINITY : q.best[i];
        boolean found = false;
        int kx = q.kx, ky = q.ky, kz = q.kz;
        for (int r = from; r < end && !(any && found); r++)
            if (r - from >= 64 || (skip & 1L << (r - from)) == 0)
                found |= TriangleIntersector.test(c, 9 * r, r, q.okx[i], q.oky[i], q.okz[i], kx, ky, kz, q.sx[i], q.sy[i], q.sz[i],
                        p.tMin[i], found ? h.t : q.best[i], h);
        if (!found) return 0;
        q.best[i] = h.t;
        q.position[i] = h.primitive;
        q.bu[i] = h.u;
        q.bv[i] = h.v;
        return 1;
    }
}
