package org.kdtree.kdtree;

import org.kdtree.accel.Hit;
import org.kdtree.accel.OctantSplit;
import org.kdtree.accel.PacketQuery;
import org.kdtree.accel.RayPacket;
import org.kdtree.accel.RayQuery;
import org.kdtree.accel.TriangleIntersector;
import org.kdtree.geom.Box;
import org.kdtree.geom.Ray;

/**
 * Packets of coherent rays through a 3-D kd-tree over a triangle mesh, after Wald's coherent ray
 * tracing (Wald, Slusallek, Benthin and Wagner 2001; Wald's thesis, 2004): the single-ray loop
 * ({@link MeshTraversal}) run for all the packet's rays at once, each node read once for them.
 * <ol>
 * <li>The rays share one sign per axis, so a node's near and far child are the same for all of
 * them. At an interior node each ray still active takes its own split-plane distance {@code
 * tSplit} and is sent, as it would be alone, to the near child, the far child or both ({@link
 * #decide}): a mask per ray.</li>
 * <li>If every active ray goes one way, the packet goes there. Otherwise the far child is saved
 * with the mask and intervals of the rays that go there, and the packet goes on into the near
 * child with the rays that go there, each ray's interval cut at its own {@code tSplit}, all in one
 * pass over the rays. The loops over the rays run over the range from the first active ray to the last.</li>
 * <li>At a leaf every active ray tests the leaf's triangles ({@link #leaf}), from the tree's
 * tracing layout ({@link KdTree#corners}).</li>
 * <li>A saved child is taken up with those of its rays that still need it: not blocked (any hit),
 * and starting no farther than their closest hit so far, the single ray's test. The packet stops
 * when no saved child is left, or (any hit) when every ray is blocked.</li>
 * </ol>
 * Every per-ray step is the single-ray loop's, with the same arithmetic, and a ray visits the same
 * leaves in the same order as alone; it only waits while others use nodes it does not need. It may
 * test a triangle met in an earlier leaf again (there is no mailbox per packet), which changes
 * nothing: the same test gives the same t, and of two hits equally close the lower index wins. So
 * each ray's answer is its single-ray answer, bit for bit.
 *
 * <p>A packet whose rays mix direction signs goes as one packet per octant ({@link OctantSplit});
 * rays with a zero or non-finite direction component, one at a time through the single-ray query.
 * Allocation-free per packet: the masks, intervals and stack are arrays made once. Not thread safe:
 * one per thread.
 */
final class PacketTraversal implements PacketQuery {
    private static final int BITS = Nodes.axisBits(3);
    private static final double SLACK = Traverser.SLACK;
    private static final int N = RayPacket.CAPACITY;
    /** Where a node sends a ray: bit 1 the near child, bit 2 the far one ({@link #decide}). */
    private static final int NEAR = 1, FAR = 2, BOTH = NEAR | FAR;

    private final RayQuery single;
    private final OctantSplit split;
    private final int[] nodes, refs;
    private final double[] corners;
    /** The scene box, 3 minima then 3 maxima, and a ray's clip to it ({@link MeshTraversal#clip}). */
    private final double[] scene, interval = new double[2];

    /** Per axis, per ray: origin and inverse direction. */
    private final double[][] origin = new double[3][N], inverse = new double[3][N];
    /** Per ray: the watertight test's shear ({@link MeshTraversal}'s, per ray). */
    private final int[] kx = new int[N], ky = new int[N], kz = new int[N];
    private final double[] sx = new double[N], sy = new double[N], sz = new double[N],
            okx = new double[N], oky = new double[N], okz = new double[N];
    /** Per ray: whether it takes part in the current node, its interval there and that interval widened by the slack. */
    private final boolean[] active = new boolean[N];
    private final double[] curMin = new double[N], curMax = new double[N], lo = new double[N], hi = new double[N];
    /** Per ray: its closest hit so far (primitive -1: none), or (any hit) whether it is blocked. */
    private final int[] bestPrim = new int[N];
    private final double[] bestT = new double[N], bestU = new double[N], bestV = new double[N];
    private final boolean[] blocked = new boolean[N];
    /** The saved far children: node, and per ray ({@code level * N + ray}) whether it goes there and its interval. */
    private final int[] stackNode, stackFirst, stackLast;
    private final boolean[] stackActive;
    /** The range of rays {@code [first, last)} outside which none is active at the current node (a saved child keeps its own). */
    private int first, last;
    private final double[] stackMin, stackMax;

    /**
     * @param tree   a tree over a triangle mesh (with its {@link KdTree#corners})
     * @param single its single-ray query, for single rays and the rays no octant holds
     */
    PacketTraversal(KdTree tree, RayQuery single) {
        if (tree.axisBits() != BITS || tree.corners == null)
            throw new IllegalArgumentException("packets are traced against a triangle mesh; this " + tree.dimension() + "-D tree holds other primitives");
        this.single = single;
        this.split = new OctantSplit(this::trace, single);
        nodes = tree.nodes;
        refs = tree.refs;
        corners = tree.corners;
        Box b = tree.bounds();
        scene = new double[] {b.min(0), b.min(1), b.min(2), b.max(0), b.max(1), b.max(2)};
        int depth = tree.stats().maxDepth() + 2;
        stackNode = new int[depth];
        stackFirst = new int[depth];
        stackLast = new int[depth];
        stackActive = new boolean[depth * N];
        stackMin = new double[depth * N];
        stackMax = new double[depth * N];
    }

    @Override public boolean closestHit(Ray ray, double tMin, double tMax, Hit hit) { return single.closestHit(ray, tMin, tMax, hit); }

    @Override public boolean anyHit(Ray ray, double tMin, double tMax) { return single.anyHit(ray, tMin, tMax); }

    /** {@return true: a coherent packet's rays share the node reads} */
    @Override public boolean tracesTogether() { return true; }

    /**
     * {@return false: renders stay one pixel at a time}. On Java 17 this scalar loop is slower per
     * ray than {@link MeshTraversal}: the Cornell box through the block tracer and this loop took
     * 1.17 times the processor time of the recursive tracer and single rays (median of 5 alternating
     * pairs of whole {@code render scenes:cornell-box} processes, 1.07 to 1.45; loaded machine). A
     * kernel that tests several rays at a compare may repay it.
     */
    @Override public boolean repaysBlocks() { return false; }

    @Override public void closestHits(RayPacket p) { traceAll(p, false); }

    @Override public void anyHits(RayPacket p) { traceAll(p, true); }

    /** A packet of one octant as one; else one packet per octant, and single rays for those with no octant. */
    private void traceAll(RayPacket p, boolean any) {
        int n = p.size();
        if (n == 0) return;
        int octant = p.octant(0);
        boolean coherent = octant >= 0;
        for (int i = 1; i < n && coherent; i++) coherent = p.octant(i) == octant;
        if (coherent) trace(p, any);
        else split.trace(p, any);
    }

    /** Traces a packet whose rays share one octant of directions: each ray's closest hit, or whether it is blocked. */
    private void trace(RayPacket p, boolean any) {
        int n = p.size(), count = load(p);
        int sp = 0, node = 0;
        first = 0;
        last = n;
        while (count > 0) {
            int w = Nodes.word(nodes, node);
            while (!Nodes.isLeaf(w, BITS)) {
                int axis = Nodes.axis(w, BITS), near = Nodes.leftChild(node), far = Nodes.rightChild(w, BITS);
                if (inverse[axis][0] < 0) { far = near; near = Nodes.rightChild(w, BITS); }
                int ways = decide(sp, far, axis, Nodes.split(nodes, node));
                if (ways == BOTH) sp++;
                node = ways == FAR ? far : near;
                w = Nodes.word(nodes, node);
            }
            count -= leaf(p, Nodes.leafStart(nodes, node), Nodes.leafSize(w, BITS), any);
            if (count == 0) break;                        // any hit: every ray blocked
            while (sp > 0 && !pop(sp - 1)) sp--;
            if (sp == 0) break;
            node = stackNode[--sp];
        }
        store(p, n, any);
    }

    /**
     * The per-node kernel: sends each active ray to the near child, the far one or both, by its
     * tSplit against its interval as the single-ray loop does, in one pass over the rays. The far
     * child is saved at {@code level} with the rays that go there, each from its tSplit (or its
     * interval's start) to its end; a ray that goes both ways has its interval cut at its tSplit,
     * one that goes only far leaves the near child. {@return the ways the rays go}: {@link #NEAR}
     * (nothing saved needed), {@link #FAR} (every ray goes far, with the intervals it had: the
     * save is taken back at once) or {@link #BOTH} (the save stands); the range of rays narrowed to
     * the child taken.
     */
    private int decide(int level, int far, int axis, double plane) {
        double[] o = origin[axis], iv = inverse[axis];
        int b = level * N, ways = 0, farFirst = N, farLast = 0, nearFirst = N, nearLast = 0;
        for (int i = first; i < last; i++) {
            if (!active[i]) {
                stackActive[b + i] = false;
                continue;
            }
            double t = (plane - o[i]) * iv[i];
            int g = t > hi[i] ? NEAR : t < lo[i] ? FAR : BOTH;
            ways |= g;
            if (g == NEAR) {
                stackActive[b + i] = false;
                if (nearFirst == N) nearFirst = i;
                nearLast = i + 1;
                continue;
            }
            stackActive[b + i] = true;
            stackMax[b + i] = curMax[i];
            if (farFirst == N) farFirst = i;
            farLast = i + 1;
            if (g == FAR) {
                stackMin[b + i] = curMin[i];
                active[i] = false;
                continue;
            }
            if (nearFirst == N) nearFirst = i;
            nearLast = i + 1;
            if (t == t) {                                   // NaN: the ray lies in the split plane
                stackMin[b + i] = t;
                curMax[i] = t;
                hi[i] = t + Math.abs(t) * SLACK;
            } else {
                stackMin[b + i] = curMin[i];
            }
        }
        if (ways == FAR) {
            for (int i = farFirst; i < farLast; i++) active[i] = stackActive[b + i];
            first = farFirst;
            last = farLast;
        } else {
            if (ways == BOTH) {
                stackNode[level] = far;
                stackFirst[level] = farFirst;
                stackLast[level] = farLast;
            }
            first = nearFirst;
            last = nearLast;
        }
        return ways;
    }

    /** Takes up the child saved at {@code level} with its rays not blocked that start no farther than their closest hit; {@return whether any does} */
    private boolean pop(int level) {
        int b = level * N, from = N, to = 0;
        for (int i = stackFirst[level], end = stackLast[level]; i < end; i++) {
            double start = stackMin[b + i], best = bestT[i];
            boolean a = stackActive[b + i] && !blocked[i] && start <= best + Math.abs(best) * SLACK;
            active[i] = a;
            if (!a) continue;
            double stop = stackMax[b + i];
            curMin[i] = start;
            curMax[i] = stop;
            lo[i] = start - Math.abs(start) * SLACK;
            hi[i] = stop + Math.abs(stop) * SLACK;
            if (from == N) from = i;
            to = i + 1;
        }
        first = from;
        last = to;
        return to > 0;
    }

    /**
     * The per-leaf kernel: every active ray tests the leaf's {@code size} triangles from reference
     * {@code start} on, keeping its closest hit or (any hit) stopping at its first, which blocks it.
     * {@return how many rays it blocked}
     */
    private int leaf(RayPacket p, int start, int size, boolean any) {
        if (size == 0) return 0;
        double[] c = corners;
        int newlyBlocked = 0;
        for (int i = first; i < last; i++) {
            if (!active[i]) continue;
            int x = kx[i], y = ky[i], z = kz[i], prim = bestPrim[i];
            double ox = okx[i], oy = oky[i], oz = okz[i], shx = sx[i], shy = sy[i], shz = sz[i];
            double tMin = p.tMin[i], tMax = p.tMax[i], best = bestT[i], bu = bestU[i], bv = bestV[i];
            boolean found = false;
            for (int r = start, end = start + size; r < end; r++) {
                // TriangleIntersector.test, written out as in MeshTraversal (the JIT will not inline it).
                int pr = refs[r], q = 9 * pr;
                double az = c[q + z] - oz, bz = c[q + 3 + z] - oz, cz = c[q + 6 + z] - oz;
                double ax = c[q + x] - ox - shx * az, ay = c[q + y] - oy - shy * az;
                double bx = c[q + 3 + x] - ox - shx * bz, by = c[q + 3 + y] - oy - shy * bz;
                double cx = c[q + 6 + x] - ox - shx * cz, cy = c[q + 6 + y] - oy - shy * cz;
                double u = cx * by - cy * bx, v = ax * cy - ay * cx, e = bx * ay - by * ax;
                if ((u < 0 || v < 0 || e < 0) && (u > 0 || v > 0 || e > 0)) continue;
                double det = u + v + e;
                if (det == 0) continue;
                double t = (u * az + v * bz + e * cz) * shz / det;
                if (!(t >= tMin && t <= tMax && (t < best || t == best && pr < prim))) continue;
                found = true;
                prim = pr;
                best = t;
                bu = v / det;
                bv = e / det;
                if (any) break;
            }
            if (!found) continue;
            bestPrim[i] = prim;
            bestT[i] = best;
            bestU[i] = bu;
            bestV[i] = bv;
            if (any) {
                blocked[i] = true;
                active[i] = false;
                newlyBlocked++;
            }
        }
        return newlyBlocked;
    }

    /**
     * Sets up each ray: its origin and inverse direction per axis, its clip to the scene box (the
     * single-ray loop's, with the same slack) and its shear. {@return how many rays enter the box}
     */
    private int load(RayPacket p) {
        int n = p.size(), count = 0;
        for (int i = 0; i < n; i++) {
            double ox = p.ox[i], oy = p.oy[i], oz = p.oz[i];
            if (!(ox - ox == 0 && oy - oy == 0 && oz - oz == 0))
                throw new IllegalArgumentException("ray " + i + " of the packet has a non-finite origin: " + p.ray(i, new Ray(3)));
            origin[0][i] = ox; origin[1][i] = oy; origin[2][i] = oz;
            inverse[0][i] = p.ix[i]; inverse[1][i] = p.iy[i]; inverse[2][i] = p.iz[i];
            bestPrim[i] = -1;
            bestT[i] = Double.POSITIVE_INFINITY;
            bestU[i] = bestV[i] = 0;
            blocked[i] = false;
            shear(p, i);
            active[i] = clip(p, i);
            if (active[i]) count++;
        }
        return count;
    }

    /** Clips ray {@code i} to the scene box, as {@link MeshTraversal} does: {@return whether it enters it} */
    private boolean clip(RayPacket p, int i) {
        boolean enters = MeshTraversal.clip(scene, p.ox[i], p.oy[i], p.oz[i], p.ix[i], p.iy[i], p.iz[i], p.tMin[i], p.tMax[i], interval);
        double t0 = interval[0], t1 = interval[1];
        curMin[i] = t0;
        curMax[i] = t1;
        lo[i] = t0 - Math.abs(t0) * SLACK;
        hi[i] = t1 + Math.abs(t1) * SLACK;
        return enters;
    }

    /** Ray {@code i}'s shear of the watertight test, as {@link MeshTraversal} computes it once per ray. */
    private void shear(RayPacket p, int i) {
        double dx = p.dx[i], dy = p.dy[i], dz = p.dz[i];
        int z = TriangleIntersector.maxAxis(dx, dy, dz);
        int x = z == 2 ? 0 : z + 1, y = x == 2 ? 0 : x + 1;
        double dz0 = z == 0 ? dx : z == 1 ? dy : dz;
        if (dz0 < 0) { int s = x; x = y; y = s; }
        double s = inverse[z][i];
        kx[i] = x; ky[i] = y; kz[i] = z;
        sz[i] = s;
        sx[i] = (x == 0 ? dx : x == 1 ? dy : dz) * s;
        sy[i] = (y == 0 ? dx : y == 1 ? dy : dz) * s;
        okx[i] = origin[x][i];
        oky[i] = origin[y][i];
        okz[i] = origin[z][i];
    }

    /** Writes each ray's answer to the packet, as the single-ray query gives it. */
    private void store(RayPacket p, int n, boolean any) {
        for (int i = 0; i < n; i++) {
            if (any) {
                p.recordAny(i, blocked[i]);
            } else if (bestPrim[i] < 0) {
                p.primitive[i] = -1;
                p.t[i] = Double.POSITIVE_INFINITY;
                p.u[i] = p.v[i] = 0;
            } else {
                p.primitive[i] = bestPrim[i];
                p.t[i] = bestT[i];
                p.u[i] = bestU[i];
                p.v[i] = bestV[i];
            }
        }
    }
}
