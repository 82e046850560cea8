package org.kdtree.bvh;

import org.kdtree.accel.Hit;
import org.kdtree.accel.RayPacket;
import org.kdtree.accel.TriangleIntersector;
import org.kdtree.geom.Tolerance;

/**
 * What the packet loop ({@link PacketTraversal}) derives from a coherent {@link RayPacket} before
 * its first node (the sheared frame, the planes, the ranges for a box test of the whole packet,
 * the plane-culling boxes), and each ray's state while it runs (interval start, closest hit so
 * far, limit); its kernels ({@link PacketKernel}) read and update it. Not thread safe: one per traversal.
 */
final class PacketRays {
    private static final double SLACK = Tolerance.TRAVERSAL_SLACK;
    private static final double SHRINK = 1 - SLACK, GROW = 1 + SLACK;
    private static final int N = RayPacket.CAPACITY;

    /** The watertight test's sheared frame: its axes, one for every ray (else the packet is not coherent). */
    int kx, ky, kz;
    /**
     * Per ray, once {@link #frame} is called: the shear's factors and the origin in its frame;
     * {@link #sz} and the origin's arrays are the packet's own (its inverse directions and origins on the frame's axes).
     */
    final double[] sx = new double[N], sy = new double[N];
    double[] sz, okx, oky, okz;
    /** Per ray: where box intervals start. */
    final double[] start = new double[N];
    /**
     * Per ray: the end of its interval so far (tMax, then its closest hit's t), its slack-widened
     * value (-infinity for rays past the packet's size and once an any-hit ray is blocked), the
     * hit's leaf position (-1 for none; a double, to sit in a vector lane) and barycentrics.
     */
    final double[] best = new double[N], limit = new double[N], position = new double[N], bu = new double[N], bv = new double[N];
    /** Scratch for one ray's triangle test. */
    final Hit hit = new Hit();
    /** Whether every ray has the same origin (a camera's): then {@code plane - origin} is one number for all. */
    boolean sharedOrigin;
    /** The packet loaded, and whether its frame is made (only packets that reach a leaf need it). */
    private RayPacket packet;
    private boolean framed;
    /** From a child's first word in a node of {@link Bvh#pairs} ({@link WideNodes} at width 2): the near and far plane of each axis. */
    int nx, ny, nz, fx, fy, fz;
    /** The packet's ranges of origins and inverse directions, and the least start of an interval ({@link #packetEnters}). */
    private double oxLo, oxHi, oyLo, oyHi, ozLo, ozHi, ixLo, ixHi, iyLo, iyHi, izLo, izHi, startLo;
    /** The boxes of the rays' origins and of their ends (min x, y, z, max x, y, z), when {@link #planeCull} ({@link #sidedTriangles}). */
    private final double[] origins = new double[6], ends = new double[6];
    /** Whether {@link #sidedTriangles} may skip triangles: an any-hit packet whose rays all end. */
    boolean planeCull;

    /**
     * Whether the packet suits the packet loop (one sign per axis, no zero or non-finite component,
     * finite origins, {@code 0 <= tMin <= tMax}, one sheared frame); if so, derives its bounds,
     * frame, planes and (for {@code any}) plane-culling boxes, and sets each ray's state.
     */
    boolean load(RayPacket p, boolean any) {
        int n = p.size();
        boolean xs = p.ix[0] < 0, ys = p.iy[0] < 0, zs = p.iz[0] < 0, ok = true;
        double oxl = Double.POSITIVE_INFINITY, oxh = Double.NEGATIVE_INFINITY, oyl = oxl, oyh = oxh, ozl = oxl, ozh = oxh;
        double ixl = oxl, ixh = oxh, iyl = oxl, iyh = oxh, izl = oxl, izh = oxh, sl = oxl;
        int z = TriangleIntersector.maxAxis(p.dx[0], p.dy[0], p.dz[0]);
        for (int i = 0; i < n; i++) {
            double ox = p.ox[i], oy = p.oy[i], oz = p.oz[i], ix = p.ix[i], iy = p.iy[i], iz = p.iz[i], t0 = p.tMin[i];
            // x - x == 0 exactly when x is finite.
            ok &= ix - ix == 0 & iy - iy == 0 & iz - iz == 0 & ix < 0 == xs & iy < 0 == ys & iz < 0 == zs
                    & t0 >= 0 & t0 <= p.tMax[i] & ox - ox == 0 & oy - oy == 0 & oz - oz == 0
                    & TriangleIntersector.maxAxis(p.dx[i], p.dy[i], p.dz[i]) == z;
            // Compares, not Math.min/max (whose NaN and -0 cases cost): a NaN makes the packet incoherent anyway.
            oxl = ox < oxl ? ox : oxl; oxh = ox > oxh ? ox : oxh;
            oyl = oy < oyl ? oy : oyl; oyh = oy > oyh ? oy : oyh;
            ozl = oz < ozl ? oz : ozl; ozh = oz > ozh ? oz : ozh;
            ixl = ix < ixl ? ix : ixl; ixh = ix > ixh ? ix : ixh;
            iyl = iy < iyl ? iy : iyl; iyh = iy > iyh ? iy : iyh;
            izl = iz < izl ? iz : izl; izh = iz > izh ? iz : izh;
            double s0 = WideTraversal.boxStart(t0);
            start[i] = s0;
            sl = s0 < sl ? s0 : sl;
            best[i] = p.tMax[i];
            limit[i] = best[i] + Math.abs(best[i]) * SLACK;
            position[i] = -1;
        }
        if (!ok) return false;
        java.util.Arrays.fill(limit, n, N, Double.NEGATIVE_INFINITY);
        oxLo = oxl; oxHi = oxh; oyLo = oyl; oyHi = oyh; ozLo = ozl; ozHi = ozh;
        ixLo = ixl; ixHi = ixh; iyLo = iyl; iyHi = iyh; izLo = izl; izHi = izh; startLo = sl;
        sharedOrigin = oxl == oxh & oyl == oyh & ozl == ozh;
        packet = p;
        framed = false;
        // The frame's axes as the single ray's (the direction's sign on z is the same for every ray of a coherent packet).
        kz = z;
        kx = z == 2 ? 0 : z + 1;
        ky = kx == 2 ? 0 : kx + 1;
        if (axis(p.dx, p.dy, p.dz, z)[0] < 0) { int t = kx; kx = ky; ky = t; }
        // Per axis a the two minima at 4 a, the two maxima at 4 a + 2.
        nx = xs ? 2 : 0; ny = ys ? 6 : 4; nz = zs ? 10 : 8;
        fx = 2 - nx; fy = 10 - ny; fz = 18 - nz;
        planeCull = any && segmentBoxes(p, n);
        return true;
    }

    /**
     * Makes each ray's shear for the watertight test, as the single-ray loop computes it, at the
     * packet's first leaf (a packet that misses every box never needs it); then again does nothing.
     */
    void frame() {
        if (framed) return;
        framed = true;
        RayPacket p = packet;
        sz = axis(p.ix, p.iy, p.iz, kz);
        okx = axis(p.ox, p.oy, p.oz, kx);
        oky = axis(p.ox, p.oy, p.oz, ky);
        okz = axis(p.ox, p.oy, p.oz, kz);
        double[] dkx = axis(p.dx, p.dy, p.dz, kx), dky = axis(p.dx, p.dy, p.dz, ky), s = sz;
        for (int i = 0, n = p.size(); i < n; i++) {
            sx[i] = dkx[i] * s[i];
            sy[i] = dky[i] * s[i];
        }
    }

    private static double[] axis(double[] x, double[] y, double[] z, int axis) {
        return axis == 0 ? x : axis == 1 ? y : z;
    }

    /** {@return the largest limit of a ray of the packet} (none NaN; those past its size are -infinity), by compares */
    double maxLimit() {
        double m = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < N; i++) m = limit[i] > m ? limit[i] : m;
        return m;
    }

    /**
     * Whether some ray of the packet may enter the box at word {@code b} of {@code nd}, its
     * intervals ending by {@code limitHi} (Wald, Boulos and Shirley's interval test): the smallest
     * near-plane distance and the largest far-plane distance over the ranges of origins and inverse
     * directions (the four corners of each product), compared as one ray's would be. Rounding is
     * monotonic, so a bound is never inside any ray's own value: false means no ray enters.
     */
    boolean packetEnters(int[] nd, int b, double limitHi) {
        double t0 = Math.max(startLo, low(Float.intBitsToFloat(nd[b + nx]), oxLo, oxHi, ixLo, ixHi));
        t0 = Math.max(t0, low(Float.intBitsToFloat(nd[b + ny]), oyLo, oyHi, iyLo, iyHi));
        t0 = Math.max(t0, low(Float.intBitsToFloat(nd[b + nz]), ozLo, ozHi, izLo, izHi));
        double t1 = Math.min(limitHi, high(Float.intBitsToFloat(nd[b + fx]), oxLo, oxHi, ixLo, ixHi));
        t1 = Math.min(t1, high(Float.intBitsToFloat(nd[b + fy]), oyLo, oyHi, iyLo, iyHi));
        t1 = Math.min(t1, high(Float.intBitsToFloat(nd[b + fz]), ozLo, ozHi, izLo, izHi));
        return t0 * SHRINK <= t1 * GROW;
    }

    /** {@return ray {@code i}'s entry distance into the box at word {@code b} of {@code nd}}, for ordering a node's children */
    double entry(RayPacket p, int[] nd, int b, int i) {
        double t0 = (Float.intBitsToFloat(nd[b + nx]) - p.ox[i]) * p.ix[i];
        t0 = Math.max(t0, (Float.intBitsToFloat(nd[b + ny]) - p.oy[i]) * p.iy[i]);
        return Math.max(t0, (Float.intBitsToFloat(nd[b + nz]) - p.oz[i]) * p.iz[i]);
    }

    /** The least {@code (plane - o) * i} over the packet's ranges (a product's extremes are at its corners). */
    private static double low(double plane, double oLo, double oHi, double iLo, double iHi) {
        double dLo = plane - oHi, dHi = plane - oLo;
        return Math.min(Math.min(dLo * iLo, dLo * iHi), Math.min(dHi * iLo, dHi * iHi));
    }

    /** The greatest {@code (plane - o) * i} over the packet's ranges. */
    private static double high(double plane, double oLo, double oHi, double iLo, double iHi) {
        double dLo = plane - oHi, dHi = plane - oLo;
        return Math.max(Math.max(dLo * iLo, dLo * iHi), Math.max(dHi * iLo, dHi * iHi));
    }

    /** Sets {@link #origins} and {@link #ends}; false (no plane culling) if some ray has no finite end. */
    private boolean segmentBoxes(RayPacket p, int n) {
        for (int a = 0; a < 3; a++) {
            origins[a] = ends[a] = Double.POSITIVE_INFINITY;
            origins[3 + a] = ends[3 + a] = Double.NEGATIVE_INFINITY;
        }
        for (int i = 0; i < n; i++) {
            double t = p.tMax[i];
            double ex = p.ox[i] + t * p.dx[i], ey = p.oy[i] + t * p.dy[i], ez = p.oz[i] + t * p.dz[i];
            if (!(Double.isFinite(ex) && Double.isFinite(ey) && Double.isFinite(ez))) return false;
            grow(origins, p.ox[i], p.oy[i], p.oz[i]);
            grow(ends, ex, ey, ez);
        }
        return true;
    }

    private static void grow(double[] b, double x, double y, double z) {
        b[0] = Math.min(b[0], x); b[1] = Math.min(b[1], y); b[2] = Math.min(b[2], z);
        b[3] = Math.max(b[3], x); b[4] = Math.max(b[4], y); b[5] = Math.max(b[5], z);
    }

    /**
     * The leaf's triangles (positions {@code [from, end)} of {@code c}, the first 64) that no ray of
     * the packet can hit, as bits: those whose plane has the box of the rays' origins and the box of
     * their ends both on one side of it, by a margin ({@link Tolerance#PLANE_SIDE_MARGIN} of the
     * distances' size) far above the rounding of the plane's normal and of the watertight test.
     * Every ray's segment lies between its origin and its end, so none reaches the plane, and the
     * single ray's test of that triangle fails too: skipping it changes no answer. Only when
     * {@link #planeCull}. Bit {@code r - from} is set for each triangle {@code r} that may be skipped.
     */
    long sidedTriangles(double[] c, int from, int end) {
        long bits = 0;
        for (int r = from, m = Math.min(end, from + 64); r < m; r++) {
            int b = 9 * r;
            double ax = c[b], ay = c[b + 1], az = c[b + 2];
            double ux = c[b + 3] - ax, uy = c[b + 4] - ay, uz = c[b + 5] - az;
            double vx = c[b + 6] - ax, vy = c[b + 7] - ay, vz = c[b + 8] - az;
            double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
            int so = side(origins, ax, ay, az, nx, ny, nz);
            if (so != 0 && so == side(ends, ax, ay, az, nx, ny, nz)) bits |= 1L << (r - from);
        }
        return bits;
    }

    /** 1 if the box lies clearly on the side of the plane through a (ax, ay, az) that its normal n points to, -1 if clearly on the other, else 0. */
    private static int side(double[] box, double ax, double ay, double az, double nx, double ny, double nz) {
        double lx = box[0] - ax, ly = box[1] - ay, lz = box[2] - az, hx = box[3] - ax, hy = box[4] - ay, hz = box[5] - az;
        double lo = Math.min(nx * lx, nx * hx) + Math.min(ny * ly, ny * hy) + Math.min(nz * lz, nz * hz);
        double hi = Math.max(nx * lx, nx * hx) + Math.max(ny * ly, ny * hy) + Math.max(nz * lz, nz * hz);
        double size = Math.abs(nx) * Math.max(Math.abs(lx), Math.abs(hx)) + Math.abs(ny) * Math.max(Math.abs(ly), Math.abs(hy))
                + Math.abs(nz) * Math.max(Math.abs(lz), Math.abs(hz));
        double margin = Tolerance.PLANE_SIDE_MARGIN * size;
        return lo > margin ? 1 : hi < -margin ? -1 : 0;
    }

    /** {@return whether {@link #sidedTriangles}'s bits {@code skip} cover every one of a leaf's {@code count} triangles} */
    static boolean skipsAll(long skip, int count) {
        return count <= 64 && skip == -1L >>> (64 - count);
    }
}
