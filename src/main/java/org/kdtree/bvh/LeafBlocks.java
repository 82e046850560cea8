package org.kdtree.bvh;

import java.util.Arrays;

/**
 * A {@link Bvh}'s triangles in blocks of {@link #WIDTH}, for a single ray to test a leaf's
 * triangles together in vector lanes (the vector path, {@code VectorTraversal}): each leaf's
 * triangles, in leaf order, fill {@code ceil(count / WIDTH)} blocks of their own, each block
 * structure-of-arrays: for corner 0, 1, 2 and axis x, y, z, the {@link #WIDTH} triangles'
 * coordinate side by side. Lanes past a leaf's last triangle, and degenerate triangles, hold NaN
 * (as {@link org.kdtree.accel.TriangleIntersector#corners} marks them), which no test accepts.
 * The values are the leaf-ordered corners' own: a lane computes exactly what the one-triangle
 * test computes.
 */
final class LeafBlocks {
    /** Triangles per block: four doubles, a 256-bit vector (AVX2 and AVX-512 alike). */
    static final int WIDTH = 4;
    /** Doubles per block: 3 corners x 3 axes x {@link #WIDTH}. */
    static final int STRIDE = 9 * WIDTH;

    /** The blocks, {@link #STRIDE} doubles each. */
    final double[] coordinates;
    /** For each leaf-order position that starts a leaf, the index of the leaf's first block. */
    final int[] firstBlock;

    LeafBlocks(Bvh bvh, double[] corners) {
        int refs = corners.length / 9, blocks = 0;
        firstBlock = new int[Math.max(1, refs)];
        for (int n = 0; n < bvh.nodeCount(); n++)
            if (bvh.isLeaf(n) && bvh.leafSize(n) > 0) blocks += (bvh.leafSize(n) + WIDTH - 1) / WIDTH;
        coordinates = new double[STRIDE * blocks];
        Arrays.fill(coordinates, Double.NaN);
        int next = 0;
        for (int n = 0; n < bvh.nodeCount(); n++) {
            if (!bvh.isLeaf(n) || bvh.leafSize(n) == 0) continue;
            int start = bvh.leafStart(n), count = bvh.leafSize(n);
            firstBlock[start] = next;
            for (int i = 0; i < count; i++) {
                int block = next + i / WIDTH, lane = i % WIDTH, r = start + i;
                for (int k = 0; k < 9; k++) coordinates[STRIDE * block + WIDTH * k + lane] = corners[9 * r + k];
            }
            next += (count + WIDTH - 1) / WIDTH;
        }
    }
}
