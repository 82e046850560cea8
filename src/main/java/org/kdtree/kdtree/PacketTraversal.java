package org.kdtree.kdtree;

import org.kdtree.accel.Hit;
import org.kdtree.accel.OctantSplit;
import org.kdtree.accel.PacketQuery;
import org.kdtree.accel.RayPacket;
import org.kdtree.accel.RayQuery;
import org.kdtree.accel.SlabClip;
import org.kdtree.accel.Vectorization;
import org.kdtree.geom.Box;
import org.kdtree.geom.Ray;

/**
 * Packets of coherent rays through a 3-D kd-tree over a triangle mesh, after Wald's coherent ray
 * tracing (Wald, Slusallek, Benthin and Wagner 2001; Wald's thesis, 2004): the single-ray loop
 * ({@link MeshTraversal}) run for all the packet's rays at once, each node read once for them. The
 * rays are lanes ({@link PacketLanes}); a set of lanes is a {@code long} mask; the per-lane work is
 * the kernels' ({@link PacketKernel}: a lane at a time on Java 17, several a compare with the
 * Vector API), this loop is written once over them.
 * <ol>
 * <li>The rays share one sign per axis, so a node's near and far child are the same for all of
 * them. At an interior node each active lane takes its own split-plane distance {@code tSplit}
 * and goes, as its ray would alone, to the near child, the far child or both (the node kernel):
 * two masks.</li>
 * <li>If every active lane goes far, the packet goes there. Otherwise the far child is saved with
 * the lanes that go there and their intervals, and the packet goes on into the near child with the
 * lanes that go there, each interval cut at its own {@code tSplit}.</li>
 * <li>At a leaf every active lane tests the leaf's triangles (the leaf kernel), from the tree's
 * tracing layout ({@link KdTree#corners}).</li>
 * <li>A saved child is taken up with those of its lanes that still need it: not blocked (any hit),
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
 * Allocation-free per packet: the lanes, intervals and stack are arrays made once. Not thread safe:
 * one per thread.
 */
final class PacketTraversal implements PacketQuery {
    private static final int BITS = Nodes.axisBits(3);
    private static final double SLACK = Traverser.SLACK;
    private static final int N = PacketLanes.N;
    /** The kernels every packet loop of this JVM calls, chosen once ({@link PacketKernel}). */
    static final PacketKernel KERNEL = Vectorization.kernel(PacketKernel.class, "org.kdtree.kdtree.VectorPacketKernel",
            new ScalarPacketKernel());

    private final RayQuery single;
    private final OctantSplit split;
    private final int[] nodes, refs;
    private final double[] corners;
    /** The scene box, 3 minima then 3 maxima, and a ray's clip to it ({@link SlabClip#clip3}). */
    private final double[] scene, interval = new double[2];
    private final PacketLanes lanes = new PacketLanes();
    /** The lanes blocked so far (any hit). */
    private long blocked;
    /** The saved far children: node and lanes per level, and per lane ({@code level * N + lane}) its interval there. */
    private final int[] stackNode;
    private final long[] stackLanes;
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
        stackLanes = new long[depth];
        stackMin = new double[depth * N];
        stackMax = new double[depth * N];
    }

    /** {@return whether this JVM's packet loops test several lanes a compare (the Vector API kernels)} */
    static boolean vectorKernels() {
        return !(KERNEL instanceof ScalarPacketKernel);
    }

    @Override public boolean closestHit(Ray ray, double tMin, double tMax, Hit hit) { return single.closestHit(ray, tMin, tMax, hit); }

    @Override public boolean anyHit(Ray ray, double tMin, double tMax) { return single.anyHit(ray, tMin, tMax); }

    /** {@return true: a coherent packet's rays share the node reads} */
    @Override public boolean tracesTogether() { return true; }

    /**
     * {@return false: renders stay one pixel at a time}, on both paths. On Java 17 this loop is
     * slower per ray than {@link MeshTraversal}: the Cornell box through the block tracer took 1.17
     * times the processor time of the recursive tracer and single rays (median of 5 alternating
     * pairs of whole {@code render scenes:cornell-box} processes, 1.07 to 1.45; loaded machine).
     * With the vector kernels (JDK 25, AVX-512), set P runs faster in packets than alone, but the
     * render through the block tracer took 2.7 times as long (medians of 3 alternating rounds, 4.06
     * s against 1.49 s; 1.4 to 2.1 times at 32 samples a pixel; loaded machine): the Vector API's
     * code runs unintrinsified until C2 compiles it, and the block tracer's bookkeeping costs about
     * as much as the kernels (docs/traversal.md).
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
        PacketLanes l = lanes;
        long entered = load(p), active = entered;
        blocked = 0;
        int sp = 0, node = 0;
        while (active != 0) {
            int w = Nodes.word(nodes, node);
            while (!Nodes.isLeaf(w, BITS)) {
                int axis = Nodes.axis(w, BITS), near = Nodes.leftChild(node), far = Nodes.rightChild(w, BITS);
                if (l.inverse[axis][0] < 0) { far = near; near = Nodes.rightChild(w, BITS); }
                KERNEL.node(l, active, axis, Nodes.split(nodes, node), stackMin, stackMax, sp * N);
                if (l.toNear == 0) {                       // every lane goes far, with the interval it had
                    node = far;
                } else {
                    if (l.toFar != 0) {
                        stackNode[sp] = far;
                        stackLanes[sp++] = l.toFar;
                    }
                    active = l.toNear;
                    node = near;
                }
                w = Nodes.word(nodes, node);
            }
            int start = Nodes.leafStart(nodes, node), end = start + Nodes.leafSize(w, BITS);
            if (start < end && !any) {
                KERNEL.closest(l, active, refs, start, end, corners);
            } else if (start < end) {
                blocked |= KERNEL.any(l, active, refs, start, end, corners);
                if ((entered & ~blocked) == 0) break;      // every ray blocked
            }
            active = 0;
            while (sp > 0 && (active = pop(sp - 1)) == 0) sp--;
            if (sp == 0) break;
            node = stackNode[--sp];
        }
        store(p, p.size(), any);
    }

    /** Takes up the child saved at {@code level} with its lanes not blocked that start no farther than their closest hit; {@return those lanes} */
    private long pop(int level) {
        long saved = stackLanes[level] & ~blocked;
        return saved == 0 ? 0 : KERNEL.resume(lanes, saved, stackMin, stackMax, level * N);
    }

    /**
     * Sets up each lane ({@link PacketLanes#load}) and its clip to the scene box (the single-ray
     * loop's, with the same slack). {@return the lanes whose rays enter the box}
     */
    private long load(RayPacket p) {
        PacketLanes l = lanes;
        long entered = 0;
        l.clearAxes();
        for (int i = 0, n = p.size(); i < n; i++) {
            double ox = p.ox[i], oy = p.oy[i], oz = p.oz[i];
            if (!(ox - ox == 0 && oy - oy == 0 && oz - oz == 0))
                throw new IllegalArgumentException("ray " + i + " of the packet has a non-finite origin: " + p.ray(i, new Ray(3)));
            l.load(p, i);
            boolean enters = SlabClip.clip3(scene, ox, oy, oz, p.ix[i], p.iy[i], p.iz[i], p.tMin[i], p.tMax[i], interval);
            double t0 = interval[0], t1 = interval[1];
            l.curMin[i] = t0;
            l.curMax[i] = t1;
            l.lo[i] = t0 - Math.abs(t0) * SLACK;
            l.hi[i] = t1 + Math.abs(t1) * SLACK;
            if (enters) entered |= 1L << i;
        }
        return entered;
    }

    /** Writes each ray's answer to the packet, as the single-ray query gives it. */
    private void store(RayPacket p, int n, boolean any) {
        PacketLanes l = lanes;
        for (int i = 0; i < n; i++) {
            if (any) {
                p.recordAny(i, (blocked >>> i & 1) != 0);
            } else if (l.bestPrim[i] < 0) {
                p.recordMiss(i);
            } else {
                p.record(i, (int) l.bestPrim[i], l.bestT[i], l.bestU[i], l.bestV[i]);
            }
        }
    }
}
