package org.kdtree.shape;

import org.kdtree.geom.Box;
import org.kdtree.geom.Tolerance;
import org.kdtree.geom.TriangleClipper;

/**
 * A 3-D triangle mesh in flat arrays: vertex coordinates (x, y, z per vertex) and vertex
 * indices (three per triangle). A million triangles take about 36 MB plus 24 MB per
 * million vertices.
 *
 * <p>Degenerate (zero-area) triangles are kept: builders handle them and ray queries
 * never report a hit on them. Non-finite coordinates are rejected, naming the triangle.
 */
public final class TriangleMesh implements Primitives {
    private final double[] vertices;
    private final int[] indices;

    /**
     * @param vertices x, y, z per vertex (not copied)
     * @param indices  three 0-based vertex indices per triangle (not copied)
     * @throws InvalidGeometryException for an index out of range, a non-finite coordinate, or a
     *         mesh outside the range ray queries support ({@link Tolerance#MAX_COORDINATE},
     *         {@link Tolerance#MIN_EXTENT})
     */
    public TriangleMesh(double[] vertices, int[] indices) {
        if (vertices.length % 3 != 0) throw new IllegalArgumentException("vertex array length must be a multiple of 3");
        if (indices.length % 3 != 0) throw new IllegalArgumentException("index array length must be a multiple of 3");
        this.vertices = vertices;
        this.indices = indices;
        int nv = vertices.length / 3;
        for (int t = 0; t < indices.length / 3; t++) {
            for (int c = 0; c < 3; c++) {
                int v = indices[3 * t + c];
                if (v < 0 || v >= nv)
                    throw new InvalidGeometryException(describe(t) + " refers to vertex " + v + " of " + nv);
                for (int a = 0; a < 3; a++) {
                    double x = vertices[3 * v + a];
                    if (!Double.isFinite(x))
                        throw new InvalidGeometryException(describe(t) + " has a non-finite coordinate (" + x + ") at vertex " + v);
                    if (Math.abs(x) > Tolerance.MAX_COORDINATE)
                        throw new InvalidGeometryException(describe(t) + " has the coordinate " + x + " at vertex " + v
                                + ": the supported range is -1e100 .. 1e100 (the ray/triangle test would overflow); scale the scene down");
                }
            }
        }
        checkExtent();
    }

    /** Refuses a mesh too small for the ray/triangle test's products (a single point is allowed). */
    private void checkExtent() {
        double largest = 0;
        for (int a = 0; a < 3; a++) {
            double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
            for (int t = 0; t < indices.length; t++) {
                double x = vertices[3 * indices[t] + a];
                lo = Math.min(lo, x);
                hi = Math.max(hi, x);
            }
            if (hi > lo) largest = Math.max(largest, hi - lo);
        }
        if (largest > 0 && largest < Tolerance.MIN_EXTENT)
            throw new InvalidGeometryException("the triangles span only " + largest + ": the smallest supported extent is 1e-100"
                    + " (the ray/triangle test would underflow); scale the scene up");
    }

    /** {@return a copy of the flat vertex array (x, y, z per vertex)}: the mesh stays as built */
    public double[] vertices() { return vertices.clone(); }

    /** {@return a copy of the flat index array (three per triangle)} */
    public int[] indices() { return indices.clone(); }

    /** {@return the number of vertices} */
    public int vertexCount() { return vertices.length / 3; }

    /**
     * {@return coordinate {@code axis} of corner {@code corner} (0..2) of triangle {@code t}}
     *
     * @param t the triangle's index
     * @param corner 0, 1 or 2
     * @param axis the axis
     */
    public double corner(int t, int corner, int axis) {
        return vertices[3 * indices[3 * t + corner] + axis];
    }

    @Override public int dimension() { return 3; }
    @Override public int size() { return indices.length / 3; }

    @Override public void bounds(int t, Box dest) {
        int i0 = 3 * indices[3 * t], i1 = 3 * indices[3 * t + 1], i2 = 3 * indices[3 * t + 2];
        for (int a = 0; a < 3; a++) {
            double v0 = vertices[i0 + a], v1 = vertices[i1 + a], v2 = vertices[i2 + a];
            dest.setMin(a, Math.min(v0, Math.min(v1, v2))).setMax(a, Math.max(v0, Math.max(v1, v2)));
        }
    }

    @Override public void clip(int t, Box voxel, Box dest) {
        TriangleClipper.forThread().clip(vertices, indices[3 * t], indices[3 * t + 1], indices[3 * t + 2], voxel, dest);
    }

    /** Clips the triangle to the voxel once and cuts that polygon by the plane. */
    @Override public void clipSplit(int t, Box voxel, int axis, double xi, Box left, Box right) {
        TriangleClipper.forThread().clipSplit(vertices, indices[3 * t], indices[3 * t + 1], indices[3 * t + 2],
                voxel, axis, xi, left, right);
    }

    @Override public String describe(int t) { return "triangle " + t; }
}
