package org.kdtree.bvh;

import org.kdtree.accel.RayPacket;

/**
 * What the packet loop ({@link PacketTraversal}) asks of a group of a packet's rays at one box and
 * at one leaf, written twice: for Java 17 ({@link ScalarPacketKernel}, a group of one ray) and
 * with the Vector API ({@code VectorPacketKernel}, src/vector/java: a group of a vector's lanes),
 * chosen once at start-up ({@link PacketTraversal#KERNEL}). Each ray of a group does exactly the
 * single-ray kernels' operations in their order, so both give every ray its single-ray hit, bit
 * for bit. The rays' state (interval start, closest hit so far, limit) is {@link PacketRays}'.
 */
interface PacketKernel {
    /** {@return rays per group: a divisor of {@link RayPacket#CAPACITY}, at most 32} */
    int lanes();

    /** {@return the size up to which a packet goes one ray at a time (set-up and masks cost more than shared node reads save)} */
    int oneByOneUpTo();

    /**
     * The node kernel: the rays of the group at {@code at} (bit {@code i} for ray {@code at + i})
     * that enter the box with these near and far planes within their intervals ({@link
     * PacketRays#start}, {@link PacketRays#limit}), with the traversal's slack.
     */
    long enter(RayPacket p, PacketRays q, int at, double pnx, double pfx, double pny, double pfy, double pnz, double pfz);

    /**
     * The leaf kernel: the rays {@code bits} of the group at {@code at} test the triangles of
     * leaf positions {@code [from, end)} of the corners {@code c} (bar those of bit {@code r - from}
     * of {@code skip}) with the watertight test, in the packet's one sheared frame
     * ({@link PacketRays#frame}): a hit within the ray's interval and closer than its hit so far
     * (or as close, at a lower position) is recorded in {@code q}; for {@code any} the ray stops
     * there. Returns the rays (bits of the group) that recorded a hit; their limits are not yet updated.
     */
    long hit(RayPacket p, PacketRays q, double[] c, int from, int end, long skip, int at, long bits, boolean any);
}
