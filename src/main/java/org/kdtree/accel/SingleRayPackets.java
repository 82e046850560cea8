package org.kdtree.accel;

import org.kdtree.geom.Ray;

/**
 * Packets answered one ray at a time: each ray of a packet goes alone through a single-ray query
 * (the structure's fast loop), so its answer is that loop's. No node read is shared: this is what
 * a structure with no packet loop of its own answers packets with (the kd-tree, for now), named
 * as such ({@link #tracesTogether} is false) so that no figure passes it off as a packet loop.
 * Allocation-free per packet; not thread safe: one per thread, like its query.
 */
public final class SingleRayPackets implements PacketQuery {
    private final RayQuery single;
    private final Ray ray = new Ray(3);
    private final Hit hit = new Hit();

    /**
     * Packets over {@code single}, a query of 3-D rays.
     *
     * @param single traces each ray
     */
    public SingleRayPackets(RayQuery single) {
        this.single = single;
    }

    @Override public boolean closestHit(Ray ray, double tMin, double tMax, Hit hit) { return single.closestHit(ray, tMin, tMax, hit); }

    @Override public boolean anyHit(Ray ray, double tMin, double tMax) { return single.anyHit(ray, tMin, tMax); }

    @Override public void closestHits(RayPacket packet) { PacketQuery.oneByOne(single, packet, ray, hit); }

    @Override public void anyHits(RayPacket packet) { PacketQuery.anyOneByOne(single, packet, ray); }

    /** {@return false: each ray is traced alone} */
    @Override public boolean tracesTogether() { return false; }
}
