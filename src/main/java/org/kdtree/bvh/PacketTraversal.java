package org.kdtree.bvh;

import org.kdtree.accel.Hit;
import org.kdtree.accel.OctantSplit;
import org.kdtree.accel.PacketQuery;
import org.kdtree.accel.RayPacket;
import org.kdtree.accel.RayQuery;
import org.kdtree.accel.Vectorization;
import org.kdtree.geom.Ray;
import org.kdtree.geom.Tolerance;

/**
 * Packets of coherent rays through a 3-D {@link Bvh}'s binary tree in its wide layout at width 2
 * ({@link Bvh#pairs}: one 64-byte node with both children's boxes), the one packet loop on both
 * paths, after Overbeck, Ramamoorthi and Mark's ranged traversal (2008) with an interval test for
 * the whole packet (Wald, Boulos and Shirley 2007). The rays still in play are a mask, one bit per
 * ray; the packet kernel ({@link #KERNEL}) takes them a group at a time (one ray in Java 17, a
 * vector's lanes with the Vector API). At each node a child's box is tested for the whole packet
 * ({@link PacketRays#packetEnters}), then, if some ray may enter it, a group at a time from each
 * end of the mask ({@link PacketKernel#enter}); the nearer child (by its first ray's entry
 * distance) is taken next, the other saved with its mask. At a leaf every group's rays test its
 * box, then its triangles ({@link PacketKernel#hit}).
 * A ray enters every box it enters alone (bar those its closest hit so far rules out) and tests
 * their triangles with the same arithmetic, and of two hits equally close the lower leaf position
 * wins either way: each ray's hit is its single-ray hit, bit for bit. An any-hit ray leaves the
 * packet at its first hit, and the packet stops when none is left; leaves whose triangles no ray's
 * segment reaches are skipped ({@link PacketRays#sidedTriangles}).
 *
 * <p>A packet goes as one if coherent ({@link PacketRays#load}); one whose rays mix direction
 * signs (a tile across an axis of the camera) as one packet per octant ({@link OctantSplit}); a
 * small one ({@link PacketKernel#oneByOneUpTo}), or one with rays no octant holds, one ray at a
 * time through the single-ray loop. Allocation-free per packet; not thread safe: one per thread.
 */
final class PacketTraversal implements PacketQuery {
    /** The kernels, chosen once for the JVM: a final static, so that the JIT inlines the one class it holds. */
    static final PacketKernel KERNEL = Vectorization.kernel(PacketKernel.class, "org.kdtree.bvh.VectorPacketKernel", new ScalarPacketKernel());
    private static final int N = RayPacket.CAPACITY;
    /** Words per node of the layout at width 2, and the offset of its children's references (their counts follow, 2 words on). */
    private static final int STRIDE = 16, REFS = 12;

    /** Single rays, and the packets the loop leaves out. */
    private final RayQuery single;
    /** The nodes ({@link Bvh#pairs}), the primitive of each leaf position, the corners in leaf order. */
    private final int[] words, prim;
    private final double[] corners;
    private final boolean empty;
    /** The packet's shear, planes, bounds and each ray's state. */
    private final PacketRays rays = new PacketRays();
    /** Saved children (as {@link #code}) with the mask of rays that enter them. */
    private final int[] stackEntry;
    private final long[] stackMask;
    private final Hit hit = new Hit();
    private final Ray ray = new Ray(3);
    private final OctantSplit split;

    /** The packet loop of {@code bvh}, over a triangle mesh, with {@code single} for single rays. */
    PacketTraversal(Bvh bvh, RayQuery single) {
        if (N % KERNEL.lanes() != 0 || KERNEL.lanes() > 32) throw new IllegalStateException(KERNEL.lanes() + " lanes do not divide a packet of " + N);
        this.single = single;
        words = bvh.pairs().words;
        prim = bvh.primitiveArray();
        corners = bvh.leafCorners();
        empty = bvh.primitiveCount() == 0;
        stackEntry = new int[bvh.maxDepth() + 2];
        stackMask = new long[stackEntry.length];
        split = new OctantSplit(this::traceOctant, single);
    }

    @Override public boolean closestHit(Ray ray, double tMin, double tMax, Hit hit) {
        return single.closestHit(ray, tMin, tMax, hit);
    }

    @Override public boolean anyHit(Ray ray, double tMin, double tMax) {
        return single.anyHit(ray, tMin, tMax);
    }

    /** {@return true: a coherent packet's rays share the node reads} */
    @Override public boolean tracesTogether() { return true; }

    /**
     * {@return false: renders stay one pixel at a time}, on both paths, as the kd-tree's do: the
     * Cornell box through the block tracer and this loop took 1.04 to 1.29 times the render time of
     * the recursive tracer over the single-ray loop (docs/rendering.md). Set P is still traced in packets.
     */
    @Override public boolean repaysBlocks() { return false; }

    @Override public void closestHits(RayPacket p) {
        traceAll(p, false);
    }

    @Override public void anyHits(RayPacket p) {
        traceAll(p, true);
    }

    /** A packet as one, or (its rays' directions of several octants: a tile across an axis) as one packet per octant. */
    private void traceAll(RayPacket p, boolean any) {
        if (p.size() == 0) return;
        if (empty || p.size() <= KERNEL.oneByOneUpTo()) oneByOne(p, any);
        else if (rays.load(p, any)) trace(p, any);
        else split.trace(p, any);
    }

    /** One octant's rays ({@link OctantSplit}): a packet if enough and coherent, else one at a time. */
    private void traceOctant(RayPacket p, boolean any) {
        if (p.size() <= KERNEL.oneByOneUpTo() || !rays.load(p, any)) oneByOne(p, any);
        else trace(p, any);
    }

    private void oneByOne(RayPacket p, boolean any) {
        if (any) PacketQuery.anyOneByOne(single, p, ray);
        else PacketQuery.oneByOne(single, p, ray, hit);
    }

    /** Traces a coherent packet, {@link #rays} loaded from it: each ray's closest hit, or (for {@code any}) whether it hits anything. */
    private void trace(RayPacket p, boolean any) {
        int n = p.size();
        PacketRays q = rays;
        long all = n == N ? -1L : (1L << n) - 1, done = 0, unhit = all;
        double limitHi = q.maxLimit();
        int[] nd = words;
        int sp = 0, e = 0;
        long mask = all;
        while (true) {
            if (e >= 0) {
                int l = STRIDE * e, r = l + 1, link = l + REFS;   // child i's box starts at word i of its node
                long lm = q.packetEnters(nd, l, limitHi) ? enter(p, nd, l, mask, false) : 0;
                long rm = q.packetEnters(nd, r, limitHi) ? enter(p, nd, r, mask, false) : 0;
                if (lm != 0 && rm != 0) {
                    boolean rightFirst = q.entry(p, nd, r, Long.numberOfTrailingZeros(rm)) < q.entry(p, nd, l, Long.numberOfTrailingZeros(lm));
                    stackEntry[sp] = code(nd, rightFirst ? link : link + 1);
                    stackMask[sp++] = rightFirst ? lm : rm;
                    e = code(nd, rightFirst ? link + 1 : link);
                    mask = rightFirst ? rm : lm;
                    continue;
                }
                if ((lm | rm) != 0) {
                    e = code(nd, lm != 0 ? link : link + 1);
                    mask = lm | rm;
                    continue;
                }
            } else {
                int word = -1 - e;
                long in = enter(p, nd, word - REFS, mask, true);   // the leaf's box: its reference's slot
                if (in != 0) {
                    long changed = leaf(p, nd, word, in, any);
                    if (any) {
                        done |= changed;
                        if (done == all) break;
                    } else if ((unhit &= ~changed) == 0 && changed != 0) {
                        limitHi = q.maxLimit();   // the packet's largest limit falls only once every ray has a hit
                    }
                }
            }
            mask = 0;
            while (mask == 0 && sp > 0) mask = stackMask[--sp] & ~done;
            if (mask == 0) break;
            e = stackEntry[sp];
        }
        for (int i = 0; i < n; i++) {
            int at = (int) q.position[i];
            if (at < 0) p.recordMiss(i);
            else p.record(i, prim[at], q.best[i], q.bu[i], q.bv[i]);
        }
    }

    /**
     * {@return a child's code, from the word of its reference}: its node's index, or {@code -1 - word}
     * for a leaf (an unused slot is never entered: its box is inverted)
     */
    private static int code(int[] words, int ref) {
        return words[ref + 2] > 0 ? -1 - ref : words[ref];
    }

    /**
     * The rays of {@code mask} that may enter the box at {@code b}. For a node's child ({@code
     * everyGroup} false): from the first group with a ray that enters it to the last, those two
     * groups' rays tested, the groups between kept whole, untested. For a leaf's box ({@code
     * everyGroup}), before its triangles: every group's rays tested.
     */
    private long enter(RayPacket p, int[] nd, int b, long mask, boolean everyGroup) {
        PacketRays q = rays;
        PacketKernel k = KERNEL;
        int lanes = k.lanes();
        long group = lanes == 64 ? -1L : (1L << lanes) - 1;
        double pnx = Float.intBitsToFloat(nd[b + q.nx]), pfx = Float.intBitsToFloat(nd[b + q.fx]);
        double pny = Float.intBitsToFloat(nd[b + q.ny]), pfy = Float.intBitsToFloat(nd[b + q.fy]);
        double pnz = Float.intBitsToFloat(nd[b + q.nz]), pfz = Float.intBitsToFloat(nd[b + q.fz]);
        long out = 0;
        if (everyGroup) {
            for (int at = 0; at < N; at += lanes) {
                long bits = (mask >>> at) & group;
                if (bits != 0) out |= (bits & k.enter(p, q, at, pnx, pfx, pny, pfy, pnz, pfz)) << at;
            }
            return out;
        }
        int first = -1;
        for (int at = 0; at < N; at += lanes) {
            long bits = (mask >>> at) & group;
            if (bits == 0) continue;
            long in = bits & k.enter(p, q, at, pnx, pfx, pny, pfy, pnz, pfz);
            if (in != 0) {
                first = at;
                out = in << at;
                break;
            }
        }
        if (first < 0) return 0;
        for (int at = N - lanes; at > first; at -= lanes) {
            long bits = (mask >>> at) & group;
            if (bits == 0) continue;
            long in = bits & k.enter(p, q, at, pnx, pfx, pny, pfy, pnz, pfz);
            if (in != 0) {
                long between = at - first > lanes ? mask & (-1L << (first + lanes)) & ((1L << at) - 1) : 0;
                return out | between | in << at;
            }
        }
        return out;
    }

    /**
     * The rays of {@code mask} (which enter the leaf's box) test the triangles of the leaf whose
     * reference is at {@code word}: each its closest hit, or for {@code any} its first, which takes
     * it out of the packet (its limit set to -infinity, below every box). Returns the rays whose
     * answer changed.
     */
    private long leaf(RayPacket p, int[] nd, int word, long mask, boolean any) {
        PacketRays q = rays;
        PacketKernel k = KERNEL;
        int from = nd[word], end = from + nd[word + 2], lanes = k.lanes();
        long group = lanes == 64 ? -1L : (1L << lanes) - 1;
        long skip = any && q.planeCull ? q.sidedTriangles(corners, from, end) : 0;
        if (PacketRays.skipsAll(skip, end - from)) return 0;   // no ray can cross any of them
        q.frame();
        long changed = 0;
        for (int at = 0; at < N; at += lanes) {
            long bits = (mask >>> at) & group;
            if (bits != 0) changed |= k.hit(p, q, corners, from, end, skip, at, bits, any) << at;
        }
        for (long m = changed; m != 0; m &= m - 1) {
            int i = Long.numberOfTrailingZeros(m);
            q.limit[i] = any ? Double.NEGATIVE_INFINITY : q.best[i] + Math.abs(q.best[i]) * Tolerance.TRAVERSAL_SLACK;
        }
        return changed;
    }
}
