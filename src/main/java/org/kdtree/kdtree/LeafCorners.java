package org.kdtree.kdtree;

/**
 * The kd-tree's tracing layout: each leaf's triangles stored together, in leaf order, their
 * corners copied once per reference (a triangle in three leaves is copied three times), so that
 * the fast loop ({@link MeshTraversal}) reads a leaf's triangles one
 * after the other, without going from a reference to a triangle elsewhere in memory. Reference
 * {@code r} of {@link KdTree#refs} (primitive {@code refs[r]}) has its 9 corner coordinates at
 * {@code 9 r}, in {@link org.kdtree.accel.TriangleIntersector#corners}'s order, so the same test
 * gives the same hits bit for bit. Made with the tree, counted in its {@link KdTree#memoryBytes}.
 */
final class LeafCorners {
    private LeafCorners() {
    }

    /**
     * {@return a new array of the corners of every reference, in leaf order}
     *
     * @param corners the mesh's corners, 9 per triangle in triangle order
     * @param refs    the leaves' references, in leaf order
     */
    static double[] of(double[] corners, int[] refs) {
        double[] c = new double[9 * refs.length];
        for (int r = 0; r < refs.length; r++) System.arraycopy(corners, 9 * refs[r], c, 9 * r, 9);
        return c;
    }

    /** {@return the bytes it holds for {@code references} references: 72 each, plus the array's header} */
    static long bytes(long references) {
        return 16 + 72L * references;
    }
}
