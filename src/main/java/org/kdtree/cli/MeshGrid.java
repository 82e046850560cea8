package org.kdtree.cli;

import org.kdtree.geom.Box;
import org.kdtree.shape.TriangleMesh;

/**
 * The benchmark's scaling scene (../meshes/README.md): a mesh repeated in an n x n grid on the
 * x-z plane, copy (gx, gz) offset by (1.1 gx extent.x, 0, 1.1 gz extent.z). Copies are numbered
 * gx-major ({@code copy = gx * n + gz}); triangle {@code t} of copy {@code c} becomes
 * {@code c * T + t}, T the mesh's triangle count.
 */
public final class MeshGrid {
    private MeshGrid() {
    }

    public static TriangleMesh repeat(TriangleMesh mesh, int n) {
        if (n < 1) throw new IllegalArgumentException("grid size must be >= 1, got " + n);
        if (n == 1) return mesh;
        double[] v = mesh.vertices();
        int[] f = mesh.indices();
        Box box = vertexBounds(mesh);
        int nv = v.length / 3;
        double[] vs = new double[v.length * n * n];
        int[] fs = new int[f.length * n * n];
        for (int gx = 0; gx < n; gx++) {
            for (int gz = 0; gz < n; gz++) {
                int copy = gx * n + gz;
                double ox = 1.1 * gx * box.extent(0), oz = 1.1 * gz * box.extent(2);
                for (int i = 0; i < nv; i++) {
                    int d = copy * v.length + 3 * i;
                    vs[d] = v[3 * i] + ox;
                    vs[d + 1] = v[3 * i + 1];
                    vs[d + 2] = v[3 * i + 2] + oz;
                }
                for (int i = 0; i < f.length; i++) fs[copy * f.length + i] = f[i] + copy * nv;
            }
        }
        return new TriangleMesh(vs, fs);
    }

    /** The SPEC's bbox: min/max over all vertices, referenced or not. */
    public static Box vertexBounds(TriangleMesh mesh) {
        Box b = new Box(3);
        double[] v = mesh.vertices();
        for (int i = 0; i < v.length; i += 3) b.grow(v, i);
        return b;
    }
}
