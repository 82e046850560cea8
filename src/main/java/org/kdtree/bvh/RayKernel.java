package org.kdtree.bvh;

import org.kdtree.accel.Hit;

/**
 * What the single-ray loop ({@link WideTraversal}) asks of one node and of one leaf, written
 * twice: for Java 17 ({@link ScalarRayKernel}) and with the Vector API ({@code VectorRayKernel},
 * src/vector/java), chosen once at start-up ({@link WideTraversal#KERNEL}). Both give the same
 * answers, bit for bit: each lane does the scalar code's operations in its order.
 */
interface RayKernel {
    /** Entries past a node's width that {@link #enter} may write in its {@code t} (a vector's whole lanes). */
    int SPARE = 16;

    /**
     * The node kernel: the children of the wide node at {@code base} in {@code words} ({@link
     * WideNodes}, {@code width} children, in three dimensions) that the ray enters within {@code
     * [start, limit]} ({@code start >= 0}, {@code limit} with the slack), with the traversal's slack
     * ({@code t0 (1 - slack) <= t1 (1 + slack)}), appended in slot order: to {@code entries} what the
     * loop goes on with (the child's wide node, or {@code -1 - word} for a leaf child: the word of
     * its reference), to {@code t} where the ray enters it (and up to {@link #SPARE} entries past the
     * last may be written). The loop then reads only the children entered, with no second pass
     * over the slots. {@code nx} is where a node's near planes on x lie within it: its minima (0) if
     * the ray runs up x, else its maxima ({@code width}); {@code fx} its far planes, the others; the
     * same on y from {@code 2 width} and on z from {@code 4 width}. The ray's inverse direction
     * ({@code ix, iy, iz}) is finite: no zero component.
     *
     * @return how many children the ray enters
     */
    int enter(int[] words, int base, int width, int nx, int fx, int ny, int fy, int nz, int fz, double ox, double oy, double oz,
              double ix, double iy, double iz, double start, double limit, int[] entries, double[] t);

    /**
     * {@return the children per node of the layout {@link #enter} reads, for a hierarchy built with
     * {@code asked}}: the Java 17 kernel takes {@code asked}; the Vector API kernel its lanes (8
     * with AVX-512, 4 with AVX2), whatever was asked, the width that measured fastest on that path
     */
    int width(int asked);

    /** {@return triangles per block of the leaf layout {@link #hit} reads ({@link LeafBlocks})} */
    int blockWidth();

    /**
     * The leaf kernel: the watertight test ({@link org.kdtree.accel.TriangleIntersector#test}) of
     * a leaf's {@code count} triangles, leaf positions from {@code first}, in the blocks of {@code
     * blocks} from {@code firstBlock[first]} ({@link LeafBlocks}; one-triangle blocks are the
     * positions themselves, and their kernel reads no index: a cache miss a leaf saved): the
     * closest hit within {@code [tMin, tMax]} and closer than {@code hit} (of two equally close, the
     * lower position) is recorded in {@code hit}, with its position as the primitive; for {@code
     * any}, the first block with a hit ends the test.
     *
     * @return the leaf position recorded, or -1
     */
    int hit(double[] blocks, int[] firstBlock, int first, int count, double okx, double oky, double okz, int kx, int ky, int kz,
            double sx, double sy, double sz, double tMin, double tMax, Hit hit, boolean any);
}
