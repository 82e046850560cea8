package org.kdtree.render;

import java.util.Arrays;
import org.kdtree.accel.PacketQuery;

/**
 * The light samples of a block's shaded points ({@link LightSamples}) put aside: per point and
 * slot (a light's sample: an area light has one per sample, other lights one), the light it would
 * bring and the shadow ray that may block it. The shadow rays are then traced as packets ({@link OctantPackets}, any hit)
 * and each point's light summed in the slots' order, as the recursive tracer sums it ray by ray. The arrays
 * grow with the most points a block has needed and are kept: nothing is allocated per point.
 */
final class Shadows {
    /** A slot's state for a point: no light; light without a shadow ray; light behind a shadow ray. */
    private static final byte NONE = 0, LIGHT = 1, SHADOWED = 2;

    private final int slots;
    /** Per point and slot ({@code point * slots + slot}): state, light (3 each), shadow ray, and whether it is blocked. */
    private byte[] state = new byte[0];
    private double[] light = new double[0], tMax = light;
    private final RayColumns ray = new RayColumns();
    private boolean[] blocked = new boolean[0];
    private final double[] rgb = new double[3];
    private final OctantPackets packets;

    Shadows(PacketQuery query, int slots) {
        this.slots = slots;
        packets = new OctantPackets(query, true, (p, at) -> {
            for (int r = 0, n = p.size(); r < n; r++) blocked[at[r]] = p.found(r);
        });
    }

    /** Makes room for points {@code 0 .. points - 1}, keeping what the first ones hold. */
    void ensure(int points) {
        int n = points * slots;
        if (n <= state.length) return;
        n = Math.max(n, 2 * state.length);
        state = Arrays.copyOf(state, n);
        light = Arrays.copyOf(light, 3 * n);
        ray.grow(n);
        tMax = Arrays.copyOf(tMax, n);
        blocked = Arrays.copyOf(blocked, n);
    }

    /** Forgets what point {@code i} kept. */
    void clear(int i) {
        Arrays.fill(state, i * slots, (i + 1) * slots, NONE);
    }

    /** Keeps point {@code i}'s light samples, each in its slot with the light {@code shader} says it brings, with their shadow rays. */
    void keep(int i, LightSamples samples, Shader shader) {
        for (int j = 0, n = samples.size(); j < n; j++) {
            int e = i * slots + samples.slot(j);
            boolean shadowed = samples.shadowed(j);
            state[e] = shadowed ? SHADOWED : LIGHT;
            shader.reflected(samples, j, rgb);
            System.arraycopy(rgb, 0, light, 3 * e, 3);
            if (shadowed) {
                samples.copyShadowRay(j, ray, e);
                tMax[e] = samples.end(j);
            }
        }
    }

    /**
     * Traces the shadow rays kept for points {@code from .. to - 1} as packets: point by point, each
     * ray into the packet of its octant of directions. A packet so holds the rays of one point or a
     * few neighbouring ones (in a block's Morton order, a 2 x 2 patch), a point's rays toward the
     * lights together: rays from one origin share the boxes around it.
     */
    void trace(int from, int to) {
        RayColumns r = ray;
        for (int e = from * slots, end = to * slots; e < end; e++)
            if (state[e] == SHADOWED) packets.add(r.ox[e], r.oy[e], r.oz[e], r.dx[e], r.dy[e], r.dz[e], tMax[e], e);
        packets.flush();
    }

    /** Writes to {@code sum} the light reaching point {@code i}, summed from 0 in the slots' order over the samples not blocked. */
    void sum(int i, double[] sum) {
        double s0 = 0, s1 = 0, s2 = 0;
        for (int e = i * slots, end = e + slots; e < end; e++) {
            byte st = state[e];
            if (st == LIGHT || st == SHADOWED && !blocked[e]) {
                s0 = s0 + light[3 * e];
                s1 = s1 + light[3 * e + 1];
                s2 = s2 + light[3 * e + 2];
            }
        }
        sum[0] = s0;
        sum[1] = s1;
        sum[2] = s2;
    }
}
