package org.kdtree.bvh;

import org.kdtree.accel.Hit;
import org.kdtree.accel.OctantSplit;
import org.kdtree.accel.PacketQuery;
import org.kdtree.accel.RayPacket;
import org.kdtree.accel.RayQuery;
import org.kdtree.geom.Ray;

/**
 * What the packet traversals of a {@link Bvh}'s compact binary layout share, the Java 17 loop
 * ({@link PacketTraversal}) and the vector one ({@code VectorPacketTraversal}): the arrays they
 * read, single rays handed to the single-ray query, and which packets go as packets. A coherent
 * packet ({@link PacketRays#load}) goes to {@link #trace}; one whose rays mix direction signs goes
 * as one packet per octant ({@link OctantSplit}); a small one, or one with rays no octant holds,
 * one ray at a time. Not thread safe: one per thread.
 */
abstract class PacketLoop implements PacketQuery {
    /** Single rays, and the packets the loop leaves out. */
    private final RayQuery single;
    /** Packets of at most this many rays go one ray at a time. */
    private final int small;
    /** The records ({@link PairNodes}), the primitive of each leaf position, the corners in leaf order. */
    final int[] words, prim;
    final double[] corners;
    final boolean empty;
    /** The packet's shear, planes and bounds, loaded before {@link #trace}. */
    final PacketRays rays = new PacketRays();
    /** Scratch for one ray's test. */
    final Hit hit = new Hit();
    private final Ray ray = new Ray(3);
    private final OctantSplit split;

    /**
     * @param bvh    a hierarchy over a triangle mesh
     * @param single its single-ray query
     * @param small  packets of at most this many rays go one ray at a time
     */
    PacketLoop(Bvh bvh, RayQuery single, int small) {
        this.single = single;
        this.small = small;
        words = bvh.pairs().words;
        prim = bvh.primitiveArray();
        corners = bvh.leafCorners();
        empty = bvh.primitiveCount() == 0;
        split = new OctantSplit(this::traceOctant, single);
    }

    /**
     * Traces a coherent packet, {@link #rays} loaded from it: each ray's closest hit, or (for
     * {@code any}) whether it hits anything, written to the packet's results.
     */
    abstract void trace(RayPacket p, boolean any);

    @Override public boolean closestHit(Ray ray, double tMin, double tMax, Hit hit) {
        return single.closestHit(ray, tMin, tMax, hit);
    }

    /** {@return true: a coherent packet's rays share the node reads} */
    @Override public boolean tracesTogether() { return true; }

    @Override public boolean anyHit(Ray ray, double tMin, double tMax) {
        return single.anyHit(ray, tMin, tMax);
    }

    @Override public void closestHits(RayPacket p) {
        traceAll(p, false);
    }

    @Override public void anyHits(RayPacket p) {
        traceAll(p, true);
    }

    /** A packet as one, or (its rays' directions of several octants: a tile across an axis) as one packet per octant. */
    private void traceAll(RayPacket p, boolean any) {
        if (p.size() == 0) return;
        if (empty || p.size() <= small) oneByOne(p, any);
        else if (rays.load(p, any)) trace(p, any);
        else split.trace(p, any);
    }

    /** One octant's rays ({@link OctantSplit}): a packet if enough and coherent, else one at a time. */
    private void traceOctant(RayPacket p, boolean any) {
        if (p.size() <= small || !rays.load(p, any)) oneByOne(p, any);
        else trace(p, any);
    }

    private void oneByOne(RayPacket p, boolean any) {
        if (any) PacketQuery.anyOneByOne(single, p, ray);
        else PacketQuery.oneByOne(single, p, ray, hit);
    }
}
