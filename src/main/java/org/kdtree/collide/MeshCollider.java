package org.kdtree.collide;

import org.kdtree.accel.TriangleIntersector;
import org.kdtree.shape.TriangleMesh;

/**
 * Sphere tests against the triangles of a {@link TriangleMesh}. The points within r of a
 * triangle are the union of a slab over its face, a capsule per edge and a sphere per vertex, so
 * a moving sphere's first contact is the earliest of: touching at t = 0, the face
 * ({@link SweptTriangle}), three edges ({@link SweptSegment}) and three vertices
 * ({@link SweptPoint}). A zero-area triangle is never touched, as it is never hit by a ray
 * ({@code accel.Intersector}'s rule): radius 0 is then exactly the ray's first hit, and no
 * query depends on where a builder files a primitive without area.
 *
 * <p>Which triangles have zero area is decided exactly, by {@link TriangleIntersector} (the one
 * place that decision is made, for rays too): that is this package's one use of {@code traverse}.
 * Corners are copied into one flat array, nine doubles per triangle.
 */
public final class MeshCollider implements Collider {
    private final double[] corners;
    private final boolean[] flat;

    /**
     * Copies the triangles' corners and decides which triangles have zero area.
     *
     * @param mesh the triangles; primitive i is the mesh's triangle i
     */
    public MeshCollider(TriangleMesh mesh) {
        int n = mesh.size();
        corners = new double[9 * n];
        flat = new boolean[n];
        TriangleIntersector exact = new TriangleIntersector(mesh);
        for (int t = 0; t < n; t++) {
            for (int k = 0; k < 3; k++) for (int a = 0; a < 3; a++) corners[9 * t + 3 * k + a] = mesh.corner(t, k, a);
            flat[t] = exact.isDegenerate(t);
        }
    }

    @Override public int dimension() { return 3; }
    @Override public int size() { return flat.length; }

    /** +infinity for a zero-area triangle (out untouched). */
    @Override public double closestPoint(int i, double[] p, double[] out) {
        if (flat[i]) return Double.POSITIVE_INFINITY;
        return SweptTriangle.closestPoint(corners, 9 * i, p[0], p[1], p[2], out);
    }

    @Override public double firstContact(int i, double[] s, double[] d, double r, double tMax) {
        if (flat[i]) return Double.POSITIVE_INFINITY;
        int b = 9 * i;
        double[] c = corners;
        double sx = s[0], sy = s[1], sz = s[2], dx = d[0], dy = d[1], dz = d[2];
        if (SweptTriangle.closestPoint(c, b, sx, sy, sz, null) <= r * r) return 0;
        double t = SweptTriangle.firstContact(c, b, sx, sy, sz, dx, dy, dz, r, tMax);
        for (int e = 0; e < 3; e++) {
            int p = b + 3 * e, q = b + 3 * ((e + 1) % 3);
            t = Math.min(t, SweptSegment.firstContact(c[p], c[p + 1], c[p + 2], c[q], c[q + 1], c[q + 2],
                    sx, sy, sz, dx, dy, dz, r, tMax));
            t = Math.min(t, SweptPoint.firstContact(c[p], c[p + 1], c[p + 2], sx, sy, sz, dx, dy, dz, r, tMax));
        }
        return t;
    }

    @Override public boolean surfaceNormal(int i, double[] out) {
        if (flat[i]) return false;
        int b = 9 * i;
        double[] c = corners;
        double e1x = c[b + 3] - c[b], e1y = c[b + 4] - c[b + 1], e1z = c[b + 5] - c[b + 2];
        double e2x = c[b + 6] - c[b], e2y = c[b + 7] - c[b + 1], e2z = c[b + 8] - c[b + 2];
        double nx = e1y * e2z - e1z * e2y, ny = e1z * e2x - e1x * e2z, nz = e1x * e2y - e1y * e2x;
        double len = Math.sqrt(nx * nx + ny * ny + nz * nz);
        out[0] = nx / len; out[1] = ny / len; out[2] = nz / len;
        return true;
    }
}
