package org.kdtree.render;

import org.kdtree.geom.Ray;
import org.kdtree.shape.TriangleMesh;
import org.kdtree.traverse.Hit;
import org.kdtree.traverse.Intersector;

/** Möller-Trumbore for test-only brute-force renders (the shipped renderer uses the kd-tree's intersector). */
final class SimpleTriangleIntersector implements Intersector {
    private final TriangleMesh mesh;

    SimpleTriangleIntersector(TriangleMesh mesh) {
        this.mesh = mesh;
    }

    @Override public int dimension() { return 3; }
    @Override public int size() { return mesh.size(); }

    @Override public boolean intersect(int i, Ray ray, double tMin, double tMax, Hit hit) {
        double[] v = mesh.vertices();
        int[] ix = mesh.indices();
        int a = 3 * ix[3 * i], b = 3 * ix[3 * i + 1], c = 3 * ix[3 * i + 2];
        double e1x = v[b] - v[a], e1y = v[b + 1] - v[a + 1], e1z = v[b + 2] - v[a + 2];
        double e2x = v[c] - v[a], e2y = v[c + 1] - v[a + 1], e2z = v[c + 2] - v[a + 2];
        double dx = ray.direction(0), dy = ray.direction(1), dz = ray.direction(2);
        double px = dy * e2z - dz * e2y, py = dz * e2x - dx * e2z, pz = dx * e2y - dy * e2x;
        double det = e1x * px + e1y * py + e1z * pz;
        if (det == 0) return false;
        double inv = 1 / det;
        double tx = ray.origin(0) - v[a], ty = ray.origin(1) - v[a + 1], tz = ray.origin(2) - v[a + 2];
        double u = (tx * px + ty * py + tz * pz) * inv;
        if (u < 0 || u > 1) return false;
        double qx = ty * e1z - tz * e1y, qy = tz * e1x - tx * e1z, qz = tx * e1y - ty * e1x;
        double w = (dx * qx + dy * qy + dz * qz) * inv;
        if (w < 0 || u + w > 1) return false;
        double t = (e2x * qx + e2y * qy + e2z * qz) * inv;
        if (t < tMin || t > tMax || t >= hit.t) return false;
        hit.primitive = i;
        hit.t = t;
        hit.u = u;
        hit.v = w;
        return true;
    }
}
