package org.kdtree.kdtree;

import java.util.ArrayList;
import java.util.List;
import org.kdtree.shape.TriangleMesh;

/** Builds small test meshes triangle by triangle (no vertex sharing needed: equal coordinates are shared exactly). */
final class MeshBuilder {
    private final List<double[]> v = new ArrayList<>();
    private final List<int[]> f = new ArrayList<>();

    MeshBuilder triangle(double[] a, double[] b, double[] c) {
        int n = v.size();
        v.add(a.clone());
        v.add(b.clone());
        v.add(c.clone());
        f.add(new int[] {n, n + 1, n + 2});
        return this;
    }

    /** The quad a-b-c-d as two triangles (a, b, c) and (a, c, d). */
    MeshBuilder quad(double[] a, double[] b, double[] c, double[] d) {
        return triangle(a, b, c).triangle(a, c, d);
    }

    /** The closed surface of the box [lo, hi], 12 triangles. */
    MeshBuilder box(double x0, double y0, double z0, double x1, double y1, double z1) {
        double[][] p = new double[8][];
        for (int i = 0; i < 8; i++)
            p[i] = new double[] {(i & 1) == 0 ? x0 : x1, (i & 2) == 0 ? y0 : y1, (i & 4) == 0 ? z0 : z1};
        quad(p[0], p[2], p[3], p[1]);
        quad(p[4], p[5], p[7], p[6]);
        quad(p[0], p[1], p[5], p[4]);
        quad(p[2], p[6], p[7], p[3]);
        quad(p[0], p[4], p[6], p[2]);
        quad(p[1], p[3], p[7], p[5]);
        return this;
    }

    /** Appends every triangle of {@code m}. */
    MeshBuilder mesh(TriangleMesh m) {
        for (int t = 0; t < m.size(); t++) {
            double[][] c = new double[3][3];
            for (int k = 0; k < 3; k++) for (int a = 0; a < 3; a++) c[k][a] = m.corner(t, k, a);
            triangle(c[0], c[1], c[2]);
        }
        return this;
    }

    int size() { return f.size(); }

    TriangleMesh build() { return Scenes.mesh(v, f); }

    /** The same mesh moved by {@code offset} (its coordinates rounded as the sums round). */
    static TriangleMesh moved(TriangleMesh m, double[] offset) {
        double[] v = m.vertices().clone();
        for (int i = 0; i < v.length; i++) v[i] += offset[i % 3];
        return new TriangleMesh(v, m.indices().clone());
    }
}
