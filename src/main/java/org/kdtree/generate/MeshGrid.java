package org.kdtree.generate;

import java.util.Locale;
import org.kdtree.geom.Box;
import org.kdtree.limits.Limits;
import org.kdtree.shape.TriangleMesh;

/**
 * The benchmark spec's scaling scene (docs/benchmark-spec.md): copies of a mesh in a grid, and
 * the spec's box of a mesh, over all its vertices.
 */
public final class MeshGrid {
    private MeshGrid() {
    }

    /**
     * The mesh repeated in a g x g grid on the x-z plane, copy (gx, gz) offset by
     * (1.1 gx extent.x, 0, 1.1 gz extent.z), the extent taken over all vertices. Copies are
     * numbered gx-major ({@code copy = gx * g + gz}); triangle t of copy c becomes
     * {@code c * T + t}, T the mesh's triangle count.
     *
     * @param mesh the mesh to repeat
     * @param g copies along x and along z
     * @return the grid of {@code g * g} copies ({@code mesh} itself when g is 1)
     */
    public static TriangleMesh grid(TriangleMesh mesh, int g) {
        Limits.GRID.check("grid", g);
        if (g == 1) return mesh;
        long triangles = (long) mesh.size() * g * g, limit = 1 << 28;
        if (triangles > limit || (long) mesh.vertexCount() * g * g > limit)
            throw new IllegalArgumentException(String.format(Locale.ROOT,
                    "a %d x %d grid of %,d triangles would hold %,d; at most %,d fit", g, g, mesh.size(), triangles, limit));
        double[] v = mesh.vertices();
        int[] f = mesh.indices();
        Box box = vertexBounds(mesh);
        int nv = v.length / 3;
        double[] vs = new double[v.length * g * g];
        int[] fs = new int[f.length * g * g];
        for (int gx = 0; gx < g; gx++) {
            for (int gz = 0; gz < g; gz++) {
                int copy = gx * g + gz;
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

    /**
     * The spec's bounding box: min/max over all vertices, referenced by a triangle or not.
     *
     * @param mesh the mesh
     * @return its vertex bounds
     */
    public static Box vertexBounds(TriangleMesh mesh) {
        Box b = new Box(3);
        double[] v = mesh.vertices();
        for (int i = 0; i < v.length; i += 3) b.grow(v, i);
        return b;
    }
}
