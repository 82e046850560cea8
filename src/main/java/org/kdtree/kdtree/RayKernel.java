package org.kdtree.kdtree;

import org.kdtree.accel.Hit;

/**
 * What the kd-tree's single-ray loop ({@link MeshTraversal}) asks of a leaf, written twice: for
 * Java 17 ({@link ScalarRayKernel}) and with the Vector API ({@code VectorRayKernel}, src/vector,
 * a leaf's triangles several at a time), chosen once at start-up ({@link MeshTraversal#KERNEL}).
 * Both give the same answers, bit for bit. A node has no kernel: one ray meets one split plane,
 * a subtraction and a product, with no lanes to fill (the packet loop's node kernel fills them
 * with rays: {@link PacketKernel#node}).
 */
interface RayKernel {
    /** The most triangles {@link #hit} tests at once: {@code lanes} holds this many entries. */
    int LANES = 8;

    /**
     * The leaf kernel: the watertight test ({@link org.kdtree.accel.TriangleIntersector#test}) of
     * the triangles of references {@code refs[start]} to {@code refs[end - 1]} (their corners
     * {@code 9 refs[r]} on in {@code corners}): of the hits within {@code [tMin, tMax]} closer than
     * {@code hit} (or as close, on a lower primitive), the closest, of equals the lowest primitive,
     * is recorded in {@code hit}: what testing them one after the other records. For {@code any},
     * the first hit found ends the test. A reference whose primitive's {@code box} entry is {@code
     * stamp} is skipped, and every primitive tested gets it (the mailbox: {@link Mailbox}).
     *
     * @param lanes scratch the kernel may write, {@link #LANES} entries (the loop's own: no allocation)
     * @param box   the mailbox's stamps, one per primitive
     * @param stamp this ray's stamp
     * @return whether a hit was recorded
     */
    boolean hit(int[] refs, int start, int end, double[] corners, int[] lanes, int[] box, int stamp, double okx, double oky, double okz, int kx, int ky,
                int kz, double sx, double sy, double sz, double tMin, double tMax, Hit hit, boolean any);
}
