package org.kdtree.bvh;

import org.kdtree.accel.Hit;
import org.kdtree.accel.PacketQuery;
import org.kdtree.accel.RayPacket;
import org.kdtree.accel.RayQuery;
import org.kdtree.accel.TriangleIntersector;
import org.kdtree.geom.Ray;
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
 * <li>At a leaf, every ray of the range tests the leaf's triangles with the one watertight test.</li>
 * </ol>
 * Every per-ray test is the single-ray traversal's, in the same arithmetic, and the whole-packet
 * bounds are taken with the same operations on the extreme values (rounding is monotonic, so a
 * bound is never inside any ray's own value): a child skipped for the packet is a child no ray
 * would have entered alone. A ray may test more triangles than alone, never fewer of those that
 * hold its closest hit, and of two hits equally close the lower leaf position wins either way
 * ({@link TriangleIntersector#test}): each ray's hit is its single-ray hit, bit for bit.
 *
 * <p>Packets take one sign per axis for all their rays and no zero direction component, with
 * {@code tMin >= 0}; others (a tile across an axis of the camera) are traced one ray at a time by
 * the single-ray query. Allocation-free per packet; not thread safe: one per thread.
 */
final class PacketTraversal implements PacketQuery {
    private static final double SLACK = Tolerance.TRAVERSAL_SLACK;
    private static final double SHRINK = 1 - SLACK, GROW = 1 + SLACK;
    private static final int STRIDE = PairNodes.STRIDE, RIGHT = PairNodes.RIGHT, LINKS = PairNodes.LINKS;
    private static final int N = RayPacket.CAPACITY;

    /** Single rays, and the packets this loop leaves out. */
    private final RayQuery single;
    private final int[] words, prim;
    private final double[] corners;
    private final boolean empty;
    /** Saved children (as {@link PairTraversal}'s entries) with the range of rays that enter them. */
    private final int[] stackEntry, stackFirst, stackLast;
    /** Per ray: where box intervals start, the closest hit so far (t, leaf position, barycentrics), and its slack-widened t. */
    private final double[] start = new double[N], best = new double[N], limit = new double[N], bu = new double[N], bv = new double[N];
    private final int[] position = new int[N];
    /** Per ray: the watertight test's shear (axes, factors) and the origin in its frame. */
    private final int[] kx = new int[N], ky = new int[N], kz = new int[N];
    private final double[] sx = new double[N], sy = new double[N], sz = new double[N],
            okx = new double[N], oky = new double[N], okz = new double[N];
    private final Hit hit = new Hit();
    private final Ray ray = new Ray(3);
    /**
     * For an any-hit packet whose rays all end ({@link #planeCull}): the boxes of the rays' origins
     * and of their ends (min x, y, z, max x, y, z), which hold every point of every ray's segment
     * between them; and of a leaf's triangles, those whose plane both boxes lie clearly on one side of.
     */
    private final double[] origins = new double[6], ends = new double[6];
    private boolean planeCull;

    PacketTraversal(Bvh bvh, RayQuery single) {
        this.single = single;
        words = bvh.pairs().words;
        prim = bvh.primitiveArray();
        corners = bvh.leafCorners();
        empty = bvh.primitiveCount() == 0;
        int depth = bvh.maxDepth() + 2;
        stackEntry = new int[depth];
        stackFirst = new int[depth];
        stackLast = new int[depth];
    }

    @Override public boolean closestHit(Ray ray, double tMin, double tMax, Hit hit) {
        return single.closestHit(ray, tMin, tMax, hit);
    }

    @Override public boolean anyHit(Ray ray, double tMin, double tMax) {
        return single.anyHit(ray, tMin, tMax);
    }

    @Override public void closestHits(RayPacket p) {
        if (p.size() == 0) return;
        if (empty || !coherent(p)) PacketQuery.oneByOne(single, p, ray, hit);
        else trace(p, false);
    }

    @Override public void anyHits(RayPacket p) {
        if (p.size() == 0) return;
        if (empty || !coherent(p)) PacketQuery.anyOneByOne(single, p, ray);
        else trace(p, true);
    }

    /**
     * Traces a coherent packet: each ray's closest hit, or (for {@code any}) whether it hits
     * anything. An any-hit ray leaves the packet at its first hit (its limit set below every box's
     * entry), as a single ray stops, and the packet stops when no ray is left.
     */
    private void trace(RayPacket p, boolean any) {
        int n = p.size(), active = n;
        double oxLo = Double.POSITIVE_INFINITY, oxHi = Double.NEGATIVE_INFINITY, oyLo = oxLo, oyHi = oxHi, ozLo = oxLo, ozHi = oxHi;
        double ixLo = oxLo, ixHi = oxHi, iyLo = oxLo, iyHi = oxHi, izLo = oxLo, izHi = oxHi, startLo = oxLo;
        for (int i = 0; i < n; i++) {
            oxLo = Math.min(oxLo, p.ox[i]); oxHi = Math.max(oxHi, p.ox[i]);
            oyLo = Math.min(oyLo, p.oy[i]); oyHi = Math.max(oyHi, p.oy[i]);
            ozLo = Math.min(ozLo, p.oz[i]); ozHi = Math.max(ozHi, p.oz[i]);
            ixLo = Math.min(ixLo, p.ix[i]); ixHi = Math.max(ixHi, p.ix[i]);
            iyLo = Math.min(iyLo, p.iy[i]); iyHi = Math.max(iyHi, p.iy[i]);
            izLo = Math.min(izLo, p.iz[i]); izHi = Math.max(izHi, p.iz[i]);
            start[i] = WideTraversal.boxStart(p.tMin[i]);
            startLo = Math.min(startLo, start[i]);
            best[i] = p.tMax[i];
            limit[i] = best[i] + Math.abs(best[i]) * SLACK;
            position[i] = -1;
            shear(p, i);
        }
        // Within a child's six words: the near and far plane of each axis, the same for every ray.
        int nx = p.ix[0] < 0 ? 3 : 0, ny = p.iy[0] < 0 ? 4 : 1, nz = p.iz[0] < 0 ? 5 : 2;
        int fx = 3 - nx, fy = 5 - ny, fz = 7 - nz;
        double limitHi = maxLimit(n);
        planeCull = any && segmentBoxes(p, n);

        int[] nd = words;
        int sp = 0, e = 0, first = 0, last = n;
        while (true) {
            if (e >= 0) {
                int l = STRIDE * e, r = l + RIGHT, link = l + LINKS;
                // The whole packet's test of each child, then its range of rays.
                int lFirst = -1, lLast = -1, rFirst = -1, rLast = -1;
                if (packetEnters(nd, l, nx, ny, nz, fx, fy, fz, oxLo, oxHi, oyLo, oyHi, ozLo, ozHi,
                        ixLo, ixHi, iyLo, iyHi, izLo, izHi, startLo, limitHi)) {
                    lFirst = firstEntering(p, nd, l, nx, ny, nz, fx, fy, fz, first, last);
                    if (lFirst >= 0) lLast = lastEntering(p, nd, l, nx, ny, nz, fx, fy, fz, lFirst, last);
                }
                if (packetEnters(nd, r, nx, ny, nz, fx, fy, fz, oxLo, oxHi, oyLo, oyHi, ozLo, ozHi,
                        ixLo, ixHi, iyLo, iyHi, izLo, izHi, startLo, limitHi)) {
                    rFirst = firstEntering(p, nd, r, nx, ny, nz, fx, fy, fz, first, last);
                    if (rFirst >= 0) rLast = lastEntering(p, nd, r, nx, ny, nz, fx, fy, fz, rFirst, last);
                }
                if (lFirst >= 0 && rFirst >= 0) {
                    // Both: the near one (for its first ray) next, the other saved with its range.
                    boolean rightFirst = entry(p, nd, r, nx, ny, nz, rFirst) < entry(p, nd, l, nx, ny, nz, lFirst);
                    int near = rightFirst ? link + 2 : link, far = rightFirst ? link : link + 2;
                    stackEntry[sp] = code(nd, far);
                    stackFirst[sp] = rightFirst ? lFirst : rFirst;
                    stackLast[sp++] = rightFirst ? lLast : rLast;
                    e = code(nd, near);
                    first = rightFirst ? rFirst : lFirst;
                    last = rightFirst ? rLast : lLast;
                    continue;
                }
                if (lFirst >= 0 || rFirst >= 0) {
                    boolean left = lFirst >= 0;
                    e = code(nd, left ? link : link + 2);
                    first = left ? lFirst : rFirst;
                    last = left ? lLast : rLast;
                    continue;
                }
            } else {
                int word = -1 - e, box = boxOf(word);
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

    /** Whether all rays suit the loop: one sign per axis, no zero or non-finite component, tMin &gt;= 0, tMin &lt;= tMax. */
    private static boolean coherent(RayPacket p) {
        boolean xs = p.ix[0] < 0, ys = p.iy[0] < 0, zs = p.iz[0] < 0;
        for (int i = 0, n = p.size(); i < n; i++) {
            double ix = p.ix[i], iy = p.iy[i], iz = p.iz[i];
            if (!(Double.isFinite(ix) && Double.isFinite(iy) && Double.isFinite(iz)) || ix < 0 != xs || iy < 0 != ys || iz < 0 != zs
                    || !(p.tMin[i] >= 0 && p.tMin[i] <= p.tMax[i])
                    || !(Double.isFinite(p.ox[i]) && Double.isFinite(p.oy[i]) && Double.isFinite(p.oz[i])))
                return false;
        }
        return true;
    }

    /** Ray {@code i}'s shear for the watertight test, as {@link PairTraversal} computes it. */
    private void shear(RayPacket p, int i) {
        double dx = p.dx[i], dy = p.dy[i], dz = p.dz[i];
        int z = TriangleIntersector.maxAxis(dx, dy, dz);
        int x = z == 2 ? 0 : z + 1, y = x == 2 ? 0 : x + 1;
        if (component(dx, dy, dz, z) < 0) { int s = x; x = y; y = s; }
        double s = component(p.ix[i], p.iy[i], p.iz[i], z);
        kx[i] = x; ky[i] = y; kz[i] = z;
        sz[i] = s;
        sx[i] = component(dx, dy, dz, x) * s;
        sy[i] = component(dx, dy, dz, y) * s;
        okx[i] = component(p.ox[i], p.oy[i], p.oz[i], x);
        oky[i] = component(p.ox[i], p.oy[i], p.oz[i], y);
        okz[i] = component(p.ox[i], p.oy[i], p.oz[i], z);
    }

    private static double component(double x, double y, double z, int axis) {
        return axis == 0 ? x : axis == 1 ? y : z;
    }

    private double maxLimit(int n) {
        double m = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < n; i++) m = Math.max(m, limit[i]);
        return m;
    }

    /** The first word of the box of the leaf whose reference is at {@code word} (a record's left or right link). */
    private static int boxOf(int word) {
        return (word & -STRIDE) + 3 * ((word & (STRIDE - 1)) - LINKS);
    }

    /** A child's word for the stack: its record, or {@code -1 - link} for a leaf. */
    private static int code(int[] nd, int link) {
        return nd[link + 1] > 0 ? -1 - link : nd[link];
    }

    /**
     * Whether some ray of the packet may enter the box at {@code b}: the smallest near-plane
     * distance and the largest far-plane distance over the ranges of origins and inverse
     * directions (the four corners of each product), compared as one ray's would be.
     */
    private static boolean packetEnters(int[] nd, int b, int nx, int ny, int nz, int fx, int fy, int fz,
                                        double oxLo, double oxHi, double oyLo, double oyHi, double ozLo, double ozHi,
                                        double ixLo, double ixHi, double iyLo, double iyHi, double izLo, double izHi,
                                        double startLo, double limitHi) {
        double t0 = Math.max(startLo, low(Float.intBitsToFloat(nd[b + nx]), oxLo, oxHi, ixLo, ixHi));
        t0 = Math.max(t0, low(Float.intBitsToFloat(nd[b + ny]), oyLo, oyHi, iyLo, iyHi));
        t0 = Math.max(t0, low(Float.intBitsToFloat(nd[b + nz]), ozLo, ozHi, izLo, izHi));
        double t1 = Math.min(limitHi, high(Float.intBitsToFloat(nd[b + fx]), oxLo, oxHi, ixLo, ixHi));
        t1 = Math.min(t1, high(Float.intBitsToFloat(nd[b + fy]), oyLo, oyHi, iyLo, iyHi));
        t1 = Math.min(t1, high(Float.intBitsToFloat(nd[b + fz]), ozLo, ozHi, izLo, izHi));
        return t0 * SHRINK <= t1 * GROW;
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

    /** Whether ray {@code i} enters the box at {@code b}: {@link PairTraversal}'s test, the same operations. */
    private boolean enters(RayPacket p, int[] nd, int b, int nx, int ny, int nz, int fx, int fy, int fz, int i) {
        double ox = p.ox[i], oy = p.oy[i], oz = p.oz[i], ix = p.ix[i], iy = p.iy[i], iz = p.iz[i];
        double t0 = (Float.intBitsToFloat(nd[b + nx]) - ox) * ix, t1 = (Float.intBitsToFloat(nd[b + fx]) - ox) * ix;
        t0 = Math.max(t0, (Float.intBitsToFloat(nd[b + ny]) - oy) * iy);
        t1 = Math.min(t1, (Float.intBitsToFloat(nd[b + fy]) - oy) * iy);
        t0 = Math.max(t0, (Float.intBitsToFloat(nd[b + nz]) - oz) * iz);
        t1 = Math.min(t1, (Float.intBitsToFloat(nd[b + fz]) - oz) * iz);
        t0 = Math.max(t0, start[i]);
        t1 = Math.min(t1, limit[i]);
        return t0 * SHRINK <= t1 * GROW;
    }

    /** Ray {@code i}'s entry distance into the box at {@code b}, for ordering children. */
    private double entry(RayPacket p, int[] nd, int b, int nx, int ny, int nz, int i) {
        double t0 = (Float.intBitsToFloat(nd[b + nx]) - p.ox[i]) * p.ix[i];
        t0 = Math.max(t0, (Float.intBitsToFloat(nd[b + ny]) - p.oy[i]) * p.iy[i]);
        return Math.max(t0, (Float.intBitsToFloat(nd[b + nz]) - p.oz[i]) * p.iz[i]);
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
     * reference is at {@code word}) as {@link PairTraversal}'s any-hit ray does, stopping at its
     * first hit, which takes it out of the packet. Returns how many rays it took out.
     */
    private int anyLeaf(RayPacket p, int[] nd, int word, int box, int nx, int ny, int nz, int fx, int fy, int fz, int first, int last) {
        double[] c = corners;
        Hit h = hit;
        int from = nd[word], end = from + nd[word + 1], blocked = 0;
        long skip = planeCull ? sidedTriangles(from, end) : 0;
        if (skip == -1L >>> (64 - Math.min(64, end - from)) && end - from <= 64) return 0;   // no ray can cross any of them
        for (int i = first; i < last; i++) {
            if (position[i] >= 0 || !enters(p, nd, box, nx, ny, nz, fx, fy, fz, i)) continue;
            h.primitive = -1;
            h.t = Double.POSITIVE_INFINITY;
            for (int r = from; r < end; r++)
                if ((r - from >= 64 || (skip & 1L << (r - from)) == 0) && TriangleIntersector.test(c, 9 * r, r, okx[i], oky[i], okz[i], kx[i], ky[i], kz[i], sx[i], sy[i], sz[i],
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
     * Sets {@link #origins} and {@link #ends} to the boxes of the packet's rays' origins and of
     * their ends ({@code o + tMax d}); false (no plane culling) if some ray has no finite end.
     */
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
     * The leaf's triangles (positions {@code [from, end)}, the first 64) that no ray of the packet
     * can hit, as bits: those whose plane has the box of the rays' origins and the box of their
     * ends both on one side of it, by a margin ({@link #SIDE_MARGIN} of the distances' size) far
     * above the rounding of the plane's normal and of the watertight test. Every ray's segment lies
     * between its origin and its end, so none reaches the plane, and the single ray's test of that
     * triangle fails too: skipping it changes no answer.
     */
    private long sidedTriangles(int from, int end) {
        double[] c = corners;
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

    /** Relative margin of {@link #side}: distances within it of the plane count as on it. */
    private static final double SIDE_MARGIN = Tolerance.PLANE_SIDE_MARGIN;

    /** 1 if the box lies clearly on the side of the plane through a (ax, ay, az) that its normal n points to, -1 if clearly on the other, else 0. */
    private static int side(double[] box, double ax, double ay, double az, double nx, double ny, double nz) {
        double lx = box[0] - ax, ly = box[1] - ay, lz = box[2] - az, hx = box[3] - ax, hy = box[4] - ay, hz = box[5] - az;
        double lo = Math.min(nx * lx, nx * hx) + Math.min(ny * ly, ny * hy) + Math.min(nz * lz, nz * hz);
        double hi = Math.max(nx * lx, nx * hx) + Math.max(ny * ly, ny * hy) + Math.max(nz * lz, nz * hz);
        double size = Math.abs(nx) * Math.max(Math.abs(lx), Math.abs(hx)) + Math.abs(ny) * Math.max(Math.abs(ly), Math.abs(hy))
                + Math.abs(nz) * Math.max(Math.abs(lz), Math.abs(hz));
        double margin = SIDE_MARGIN * size;
        return lo > margin ? 1 : hi < -margin ? -1 : 0;
    }

    /**
     * Every ray of {@code [first, last)} that enters the leaf's box (at {@code box}: the range's
     * middle rays were not tested at its parent) tests the leaf's triangles (the leaf whose
     * reference is at {@code word}).
     */
    private void leaf(RayPacket p, int[] nd, int word, int box, int nx, int ny, int nz, int fx, int fy, int fz, int first, int last) {
        double[] c = corners;
        Hit h = hit;
        int from = nd[word], end = from + nd[word + 1];
        for (int i = first; i < last; i++) {
            if (!enters(p, nd, box, nx, ny, nz, fx, fy, fz, i)) continue;   // a ray of the range that misses the leaf's box
            // As the single ray: the hit so far (none: +infinity), and t up to the closest so far (at first tMax).
            h.primitive = position[i];
            h.t = position[i] < 0 ? Double.POSITIVE_INFINITY : best[i];
            boolean found = false;
            for (int r = from; r < end; r++)
                found |= TriangleIntersector.test(c, 9 * r, r, okx[i], oky[i], okz[i], kx[i], ky[i], kz[i], sx[i], sy[i], sz[i],
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
