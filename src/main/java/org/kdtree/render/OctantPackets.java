package org.kdtree.render;

import org.kdtree.accel.PacketQuery;
import org.kdtree.accel.RayPacket;

/**
 * Rays gathered into packets by their octant of directions ({@link RayPacket#octant(double, double,
 * double)}), each packet traced when it fills and the rest at {@link #flush}: the packet loops want
 * one sign per axis, and rays added in image order (a block's Morton order) fill a packet with
 * neighbours. Each ray carries the index its owner gave it, handed back with the answers.
 * Allocation-free; one per tracer.
 */
final class OctantPackets {
    /** Receives a traced packet, and per ray the index it was added with. */
    interface Traced {
        void traced(RayPacket p, int[] entries);
    }

    /** The eight octants, and one packet for directions with no octant (traced as a packet all the same: its loop sends them one at a time). */
    private static final int BINS = 9;

    private final PacketQuery query;
    private final boolean any;
    private final Traced traced;
    private final RayPacket[] packets = new RayPacket[BINS];
    private final int[][] entries = new int[BINS][RayPacket.CAPACITY];

    /**
     * @param query  the packets' query
     * @param any    whether to ask for any hit (shadow rays) instead of the closest
     * @param traced receives each traced packet
     */
    OctantPackets(PacketQuery query, boolean any, Traced traced) {
        this.query = query;
        this.any = any;
        this.traced = traced;
        for (int b = 0; b < BINS; b++) packets[b] = new RayPacket();
    }

    /** Adds the ray {@code o + t d}, {@code 0 <= t <= tMax}, known to its owner as {@code entry}. */
    void add(double ox, double oy, double oz, double dx, double dy, double dz, double tMax, int entry) {
        int o = RayPacket.octant(dx, dy, dz), b = o < 0 ? BINS - 1 : o;
        RayPacket p = packets[b];
        entries[b][p.add(ox, oy, oz, dx, dy, dz, 0, tMax)] = entry;
        if (p.size() == RayPacket.CAPACITY) trace(b);
    }

    /** Traces every packet not yet traced. */
    void flush() {
        for (int b = 0; b < BINS; b++) if (packets[b].size() > 0) trace(b);
    }

    private void trace(int b) {
        RayPacket p = packets[b];
        if (any) query.anyHits(p);
        else query.closestHits(p);
        traced.traced(p, entries[b]);
        p.clear();
    }
}
