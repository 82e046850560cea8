package org.kdtree.generate;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.kdtree.shape.TriangleMesh;

/**
 * The hard 3-D inputs built without randomness: identical triangles, zero-area triangles, a
 * grid of cubes whose faces lie in split planes, a scene scaled to extreme coordinates; and the
 * triangle soup (each triangle its own three vertices) every generated mesh is made as.
 */
public final class HardMeshes {
    private HardMeshes() {
    }

    /**
     * {@code copies} copies of one triangle, sharing its three vertices.
     *
     * @param copies how many
     * @return the mesh
     */
    public static TriangleMesh identical(int copies) {
        double[] v = {0, 0, 0, 1, 0, 0, 0, 1, 0.5};
        int[] idx = new int[3 * copies];
        for (int t = 0; t < copies; t++) {
            idx[3 * t] = 0;
            idx[3 * t + 1] = 1;
            idx[3 * t + 2] = 2;
        }
        return new TriangleMesh(v, idx);
    }

    /** {@return zero-area triangles (collinear, repeated vertex, all three equal), then two ordinary ones} */
    public static TriangleMesh degenerate() {
        double[] v = {
                0, 0, 0, 1, 1, 1, 2, 2, 2,          // collinear
                0.5, 0, 0, 0.5, 0, 0, 1, 1, 0,      // repeated vertex
                0.3, 0.3, 0.3, 0.3, 0.3, 0.3, 0.3, 0.3, 0.3, // a point
                0, 2, 0, 2, 2, 0, 0, 2, 2,          // ordinary
                1, 0, 2, 2, 0, 2, 2, 1, 2,          // ordinary
        };
        return soup(v);
    }

    /**
     * An n x n x n grid of unit cubes (12 triangles each, a gap of one between cubes): every face
     * lies in a plane the SAH will consider, so planar triangles and faces in split planes are everywhere.
     *
     * @param n the cubes per axis
     * @return the triangle soup
     */
    public static TriangleMesh cubeGrid(int n) {
        List<double[]> tris = new ArrayList<>();
        for (int i = 0; i < n; i++)
            for (int j = 0; j < n; j++)
                for (int k = 0; k < n; k++) addCube(tris, 2 * i, 2 * j, 2 * k, 1);
        return soup(tris);
    }

    /**
     * Adds the 12 triangles of an axis-aligned cube with corner (x, y, z) and side s.
     *
     * @param out receives 9 coordinates per triangle
     * @param x the corner's x
     * @param y the corner's y
     * @param z the corner's z
     * @param s the side
     */
    public static void addCube(List<double[]> out, double x, double y, double z, double s) {
        double[][] c = new double[8][];
        for (int i = 0; i < 8; i++) c[i] = new double[] {x + ((i & 1) != 0 ? s : 0), y + ((i & 2) != 0 ? s : 0), z + ((i & 4) != 0 ? s : 0)};
        int[][] quads = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
        for (int[] q : quads) {
            out.add(corners(c[q[0]], c[q[1]], c[q[2]]));
            out.add(corners(c[q[0]], c[q[2]], c[q[3]]));
        }
    }

    /**
     * Scales every coordinate of a mesh.
     *
     * @param m the mesh
     * @param s the factor
     * @return the scaled copy
     */
    public static TriangleMesh scaled(TriangleMesh m, double s) {
        double[] v = m.vertices();
        for (int i = 0; i < v.length; i++) v[i] *= s;
        return new TriangleMesh(v, m.indices());
    }

    /**
     * A triangle soup: 9 coordinates per triangle, each with its own three vertices.
     *
     * @param coords 9 coordinates per triangle
     * @return the mesh
     */
    public static TriangleMesh soup(double[] coords) {
        int[] idx = new int[coords.length / 3];
        Arrays.setAll(idx, i -> i);
        return new TriangleMesh(coords, idx);
    }

    /**
     * A triangle soup of a list of triangles.
     *
     * @param triangles 9 coordinates each
     * @return the mesh
     */
    public static TriangleMesh soup(List<double[]> triangles) {
        double[] v = new double[9 * triangles.size()];
        for (int t = 0; t < triangles.size(); t++) System.arraycopy(triangles.get(t), 0, v, 9 * t, 9);
        return soup(v);
    }

    private static double[] corners(double[] a, double[] b, double[] c) {
        double[] r = new double[9];
        System.arraycopy(a, 0, r, 0, 3);
        System.arraycopy(b, 0, r, 3, 3);
        System.arraycopy(c, 0, r, 6, 3);
        return r;
    }
}
