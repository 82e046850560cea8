package org.kdtree.scene;

import org.kdtree.shape.TriangleMesh;

/**
 * The scene's triangles in flat arrays: the mesh the kd-tree is built over, the material index
 * of each triangle, and per-vertex normals used by triangles marked smooth (tessellated spheres);
 * other triangles are shaded with their geometric normal.
 */
public final class SceneGeometry {
    private final TriangleMesh mesh;
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
        if (materialOf.length != mesh.size() || smooth.length != mesh.size() || normals.length != mesh.vertices().length)
            throw new IllegalArgumentException("per-triangle and per-vertex arrays must match the mesh");
        this.mesh = mesh;
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
     * {@return the unnormalised geometric normal (v1 - v0) x (v2 - v0) of triangle {@code t}}
     *
     * @param t the triangle's index
     */
    public Vec3 geometricNormal(int t) {
        double[] v = mesh.vertices();
        int[] ix = mesh.indices();
        int a = 3 * ix[3 * t], b = 3 * ix[3 * t + 1], c = 3 * ix[3 * t + 2];
        Vec3 e1 = new Vec3(v[b] - v[a], v[b + 1] - v[a + 1], v[b + 2] - v[a + 2]);
        Vec3 e2 = new Vec3(v[c] - v[a], v[c + 1] - v[a + 1], v[c + 2] - v[a + 2]);
        return e1.cross(e2);
    }

    /**
     * {@return the point with barycentrics (u, v) on triangle {@code t}}: exact to rounding of the vertices' size.
     *
     * @param t the triangle's index
     * @param u the first barycentric coordinate
     * @param v the second barycentric coordinate
     */
    public Vec3 point(int t, double u, double v) {
        return interpolate(mesh.vertices(), t, u, v);
    }

    /**
     * {@return the unit shading normal at (u, v)}: interpolated if the triangle is smooth, else geometric.
     *
     * @param t the triangle's index
     * @param u the first barycentric coordinate
     * @param v the second barycentric coordinate
     */
    public Vec3 shadingNormal(int t, double u, double v) {
        if (!smooth[t]) return geometricNormal(t).normalized();
        Vec3 n = interpolate(normals, t, u, v);
        return n.isZero() ? geometricNormal(t).normalized() : n.normalized();
    }

    private Vec3 interpolate(double[] a, int t, double u, double v) {
        int[] ix = mesh.indices();
        int i0 = 3 * ix[3 * t], i1 = 3 * ix[3 * t + 1], i2 = 3 * ix[3 * t + 2];
        double w = 1 - u - v;
        return new Vec3(w * a[i0] + u * a[i1] + v * a[i2],
                w * a[i0 + 1] + u * a[i1 + 1] + v * a[i2 + 1],
                w * a[i0 + 2] + u * a[i1 + 2] + v * a[i2 + 2]);
    }
}
