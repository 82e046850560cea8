package org.kdtree.bvh;

import java.util.Arrays;

/**
 * A {@link Bvh}'s triangles in blocks of {@link #width}, the leaf layout the single-ray loop's
 * leaf kernel reads ({@link RayKernel#blockWidth}): each leaf's triangles, in leaf order, fill
 * {@code ceil(count / width)} blocks of their own, each block structure-of-arrays: for corner 0,
 * 1, 2 and axis x, y, z, the {@link #width} triangles' coordinate side by side. At width 1 this is
 * the corners in leaf order themselves, 9 doubles a triangle (the Java 17 kernel's); at 4, a
 * vector of four triangles per coordinate (the Vector API kernel's). Lanes past a leaf's last
 * triangle, and degenerate triangles, hold NaN (as {@link org.kdtree.accel.TriangleIntersector#corners}
 * marks them), which no test accepts. The values are the corners' own: a lane computes exactly
 * what the one-triangle test computes.
 */
final class LeafBlocks {
    /** Triangles per block. */
    final int width;
    /** The blocks, 9 {@link #width} doubles each. */
    final double[] coordinates;
    /** For each leaf-order position that starts a leaf, the index of the leaf's first block. */
    final int[] firstBlock;

    /** The blocks of {@code bvh}'s leaves from its corners in leaf order ({@link Bvh#leafCorners}), kept as they are at width 1. */
    LeafBlocks(Bvh bvh, double[] corners, int width) {
        this.width = width;
        firstBlock = new int[Math.max(1, corners.length / 9)];
        int blocks = 0;
        for (int n = 0; n < bvh.nodeCount(); n++) {
            if (!bvh.isLeaf(n) || bvh.leafSize(n) == 0) continue;
            firstBlock[bvh.leafStart(n)] = width == 1 ? bvh.leafStart(n) : blocks;   // at width 1, the corners' own positions
            blocks += (bvh.leafSize(n) + width - 1) / width;
        }
        coordinates = width == 1 ? corners : new double[9 * width * blocks];
        if (width > 1) Arrays.fill(coordinates, Double.NaN);
        for (int n = 0; n < bvh.nodeCount() && width > 1; n++) {
            if (!bvh.isLeaf(n)) continue;
            for (int i = 0, start = bvh.leafStart(n); i < bvh.leafSize(n); i++) {
                int block = firstBlock[start] + i / width, lane = i % width;
                for (int k = 0; k < 9; k++) coordinates[9 * width * block + width * k + lane] = corners[9 * (start + i) + k];
            }
        }
    }

    /** {@return the bytes it holds beyond the corners it was made from} */
    long memoryBytes() {
        return 4L * firstBlock.length + (width == 1 ? 0 : 8L * coordinates.length);
    }
}
