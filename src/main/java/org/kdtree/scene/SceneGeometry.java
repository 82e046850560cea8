package org.kdtree.scene;

import org.kdtree.shape.TriangleMesh;

/**
 * The scene's triangles in flat arrays: the mesh the kd-tree is built over, the material index
 * of each triangle, and per-vertex normals used by triangles marked smooth (tessellated spheres);
 * other triangles are shaded with their geometric normal.
 */
public final class SceneGeometry {
    private final TriangleMesh mesh;
    /** The mesh's vertices and indices, copied once: the shading reads them per hit. */
    private final double[] vertices;
    private final int[] indices;
    private final int[] materialOf;
    private final double[] normals;
    private final boolean[] smooth;

    /**
     * Triangles with their materials and normals.
     *
     * @param mesh the triangles
     * @param materialOf per triangle: its material index; not copied
     * @param normals x, y, z per vertex (unit, or zero where unused); not copied
     * @param smooth per triangle: interpolate vertex normals; not copied
     */
    public SceneGeometry(TriangleMesh mesh, int[] materialOf, double[] normals, boolean[] smooth) {
        if (materialOf.length != mesh.size() || smooth.length != mesh.size() || normals.length != 3 * mesh.vertexCount())
            throw new IllegalArgumentException("per-triangle and per-vertex arrays must match the mesh");
        this.mesh = mesh;
        this.vertices = mesh.vertices();
        this.indices = mesh.indices();
        this.materialOf = materialOf;
        this.normals = normals;
        this.smooth = smooth;
    }

    /** {@return the triangles} */
    public TriangleMesh mesh() { return mesh; }

    /** {@return the number of triangles} */
    public int triangleCount() { return mesh.size(); }

    /**
     * {@return the material index of triangle {@code t}}
     *
     * @param t the triangle's index
     */
    public int materialOf(int t) { return materialOf[t]; }

    /**
     * Writes the unnormalised geometric normal (v1 - v0) x (v2 - v0) of triangle {@code t} to {@code out}.
     *
     * @param t the triangle's index
     * @param out receives x, y, z
     */
    public void geometricNormal(int t, double[] out) {
        double[] v = vertices;
        int[] ix = indices;
        int a = 3 * ix[3 * t], b = 3 * ix[3 * t + 1], c = 3 * ix[3 * t + 2];
        double e1x = v[b] - v[a], e1y = v[b + 1] - v[a + 1], e1z = v[b + 2] - v[a + 2];
        double e2x = v[c] - v[a], e2y = v[c + 1] - v[a + 1], e2z = v[c + 2] - v[a + 2];
        out[0] = e1y * e2z - e1z * e2y;
        out[1] = e1z * e2x - e1x * e2z;
        out[2] = e1x * e2y - e1y * e2x;
    }

    /**
     * Writes the point with barycentrics (u, v) on triangle {@code t} to {@code out}: exact to rounding of the vertices' size.
     *
     * @param t the triangle's index
     * @param u the first barycentric coordinate
     * @param v the second barycentric coordinate
     * @param out receives x, y, z
     */
    public void point(int t, double u, double v, double[] out) {
        interpolate(vertices, t, u, v, out);
    }

    /**
     * Writes the unit shading normal at (u, v) to {@code out}: interpolated if the triangle is smooth, else geometric.
     *
     * @param t the triangle's index
     * @param u the first barycentric coordinate
     * @param v the second barycentric coordinate
     * @param out receives x, y, z
     */
    public void shadingNormal(int t, double u, double v, double[] out) {
        if (smooth[t]) interpolate(normals, t, u, v, out);
        if (!smooth[t] || (out[0] == 0 && out[1] == 0 && out[2] == 0)) geometricNormal(t, out);
        Vectors.normalize(out);
    }

    private void interpolate(double[] a, int t, double u, double v, double[] out) {
        int[] ix = indices;
        int i0 = 3 * ix[3 * t], i1 = 3 * ix[3 * t + 1], i2 = 3 * ix[3 * t + 2];
        double w = 1 - u - v;
        out[0] = w * a[i0] + u * a[i1] + v * a[i2];
        out[1] = w * a[i0 + 1] + u * a[i1 + 1] + v * a[i2 + 1];
        out[2] = w * a[i0 + 2] + u * a[i1 + 2] + v * a[i2 + 2];
    }
}
