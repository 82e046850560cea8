package org.kdtree.kdtree;

import org.kdtree.accel.Hit;

/**
 * What the kd-tree's single-ray loop ({@link MeshTraversal}) asks of a leaf: the test of its
 * triangles, behind one narrow interface as the packet loop's kernels are ({@link PacketKernel}),
 * so that the loop is written once over it. One implementation, for every JVM ({@link
 * ScalarRayKernel}): a Vector API one, four triangles a test gathered by reference, gave the same
 * hits and measured no faster on JDK 25 (set R 1.01 x the time, set P 1.03 x: a leaf holds about
 * three triangles, and a random ray's time goes to reaching it; docs/traversal.md), so it was not
 * kept. A node has no kernel: one ray meets one split plane, a subtraction and a product, with no
 * lanes to fill (the packet loop's node kernel fills them with rays: {@link PacketKernel#node}).
 */
interface RayKernel {
    /**
     * The leaf kernel: the watertight test ({@link org.kdtree.accel.TriangleIntersector#test}) of
     * the triangles of references {@code refs[start]} to {@code refs[end - 1]} (their corners
     * {@code 9 refs[r]} on in {@code corners}): of the hits within {@code [tMin, tMax]} closer than
     * {@code hit} (or as close, on a lower primitive), the closest, of equals the lowest primitive,
     * is recorded in {@code hit}: what testing them one after the other records. For {@code any},
     * the first hit found ends the test. A reference whose primitive's {@code box} entry is {@code
     * stamp} is skipped, and every primitive tested gets it (the mailbox: {@link Mailbox}).
     *
     * @param box   the mailbox's stamps, one per primitive
     * @param stamp this ray's stamp
     * @return whether a hit was recorded
     */
    boolean hit(int[] refs, int start, int end, double[] corners, int[] box, int stamp, double okx, double oky, double okz, int kx, int ky,
                int kz, double sx, double sy, double sz, double tMin, double tMax, Hit hit, boolean any);
}
