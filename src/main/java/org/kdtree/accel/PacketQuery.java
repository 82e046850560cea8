package org.kdtree.accel;

import org.kdtree.geom.Ray;

/**
 * A ray query that also answers packets of rays ({@link AccelerationStructure#packetQuery}: every
 * structure gives one). A packet loop traces coherent rays together: a packet's rays share the
 * structure's node reads, and a box or cell that no ray of the packet can enter is skipped for
 * all of them at once (the BVH's and the kd-tree's loops); a query without one would answer each
 * ray of the packet alone ({@link #oneByOne}), and {@link #tracesTogether} says which it is.
 * Either way each ray's answer is exactly its {@link RayQuery#closestHit} answer (primitive, t,
 * barycentrics). Not thread safe: one per thread, like the query.
 */
public interface PacketQuery extends RayQuery {
    /**
     * {@return whether a packet's rays are traced together}, sharing the structure's node reads (a
     * packet loop), rather than each alone through the single-ray loop ({@link #oneByOne}); the
     * figures of a packet query name the loop by it
     */
    boolean tracesTogether();

    /**
     * {@return whether a renderer's block tracer, which gathers a block's rays into packets for
     * this query, is repaid}: by default where {@link #tracesTogether}; a packet loop measured
     * slower in renders than its structure's single rays says false, and renders stay one pixel at
     * a time (the same image either way)
     */
    default boolean repaysBlocks() {
        return tracesTogether();
    }

    /**
     * The closest hit of every ray of the packet, written to the packet's results.
     *
     * @param packet the rays; receives their hits
     */
    void closestHits(RayPacket packet);

    /**
     * Whether each ray of the packet hits anything in its interval (shadow rays, "any hit"):
     * {@link RayPacket#found} says so for each ray, exactly as {@link RayQuery#anyHit} answers that
     * ray alone. Which hit is recorded ({@link RayPacket#primitive}, t, barycentrics) is unspecified:
     * a packet, like a single ray, may stop at the first it finds.
     *
     * @param packet the rays; receives whether each is blocked
     */
    void anyHits(RayPacket packet);

    /**
     * The closest hits of a packet's rays one at a time, with {@code query}: what a query without
     * packets does, and what a packet query does with rays it cannot trace together.
     *
     * @param query  the single-ray query
     * @param packet the rays; receives their hits
     * @param ray    scratch, a 3-D ray
     * @param hit    scratch
     */
    static void oneByOne(RayQuery query, RayPacket packet, Ray ray, Hit hit) {
        for (int i = 0, n = packet.size(); i < n; i++) {
            query.closestHit(packet.ray(i, ray), packet.tMin[i], packet.tMax[i], hit);
            packet.record(i, hit);
        }
    }

    /**
     * Whether each ray of a packet hits anything, one ray at a time with {@code query}: what
     * {@link #anyHits} does with rays it cannot trace together.
     *
     * @param query  the single-ray query
     * @param packet the rays; receives whether each is blocked ({@link RayPacket#found})
     * @param ray    scratch, a 3-D ray
     */
    static void anyOneByOne(RayQuery query, RayPacket packet, Ray ray) {
        for (int i = 0, n = packet.size(); i < n; i++) packet.recordAny(i, query.anyHit(packet.ray(i, ray), packet.tMin[i], packet.tMax[i]));
    }
}
