package org.kdtree.collide;

/**
 * An edge of a triangle, or a 2-D segment, as something a sphere can hit: the points within r of
 * the segment PQ form a capsule, a cylinder around PQ closed by the spheres around P and Q. This
 * class answers the closest point on PQ and the first contact with the cylinder's side (the ray
 * against an infinite cylinder, kept where the touching point projects inside PQ); the end caps
 * are {@link SweptPoint}'s. In 2-D pass z = 0: the cylinder's side is then the two lines at
 * distance r.
 */
final class SweptSegment {
    private SweptSegment() {
    }

    /**
     * Writes the point of PQ closest to p into {@code out[0..3)} (unless {@code out} is null) and
     * returns the squared distance. A zero-length segment is its point.
     */
    static double closestPoint(double px, double py, double pz, double qx, double qy, double qz,
                               double x, double y, double z, double[] out) {
        double ex = qx - px, ey = qy - py, ez = qz - pz;
        double ee = ex * ex + ey * ey + ez * ez;
        double me = (x - px) * ex + (y - py) * ey + (z - pz) * ez;
        double cx, cy, cz;
        if (me <= 0 || ee == 0) { cx = px; cy = py; cz = pz; }
        else if (me >= ee) { cx = qx; cy = qy; cz = qz; }
        else {
            double u = me / ee;
            cx = px + u * ex; cy = py + u * ey; cz = pz + u * ez;
        }
        if (out != null) { out[0] = cx; out[1] = cy; out[2] = cz; }
        return SweptPoint.distanceSquared(cx, cy, cz, x, y, z);
    }

    /**
     * The smallest t in [0, tMax] at which the sphere's centre {@code s + t d} enters the side of
     * the cylinder of radius r around PQ at a point projecting inside PQ, or +infinity.
     * Precondition: the sphere does not touch PQ at t = 0 (the caller tests that first); then a
     * path starting inside the infinite cylinder, or running parallel to PQ, can only reach the
     * capsule through an end cap, which the end points' tests answer. A tangent path touches.
     */
    static double firstContact(double px, double py, double pz, double qx, double qy, double qz,
                               double sx, double sy, double sz, double dx, double dy, double dz,
                               double r, double tMax) {
        double ex = qx - px, ey = qy - py, ez = qz - pz;
        double ee = ex * ex + ey * ey + ez * ez;
        if (ee == 0) return Double.POSITIVE_INFINITY;
        double mx = sx - px, my = sy - py, mz = sz - pz;
        // Distance to the line PQ times |e| is |e x (m + t d)|: a quadratic a t^2 + 2 b t + c = 0 at
        // the surface. Cross products (not the expanded dot products) keep a and c accurate.
        double ux = ey * mz - ez * my, uy = ez * mx - ex * mz, uz = ex * my - ey * mx; // e x m
        double wx = ey * dz - ez * dy, wy = ez * dx - ex * dz, wz = ex * dy - ey * dx; // e x d
        double a = wx * wx + wy * wy + wz * wz;
        if (a == 0) return Double.POSITIVE_INFINITY; // parallel to PQ, or not moving
        double c = ux * ux + uy * uy + uz * uz - r * r * ee;
        if (c <= 0) return Double.POSITIVE_INFINITY; // inside the infinite cylinder: enters by a cap
        double b = ux * wx + uy * wy + uz * wz;
        if (b >= 0) return Double.POSITIVE_INFINITY; // moving away from the line
        // b^2 - a c = r^2 |e|^2 a - |u x w|^2 (Lagrange's identity), without the cancellation
        // (in 2-D u and w are parallel, so the second term is exactly 0).
        double vx = uy * wz - uz * wy, vy = uz * wx - ux * wz, vz = ux * wy - uy * wx;
        double disc = r * r * ee * a - (vx * vx + vy * vy + vz * vz);
        if (disc < 0) return Double.POSITIVE_INFINITY;
        double t = c / (-b + Math.sqrt(disc));
        if (t > tMax) return Double.POSITIVE_INFINITY;
        // Where along PQ does it touch? Closed: a touch exactly at P or Q counts here too.
        double h = (mx + t * dx) * ex + (my + t * dy) * ey + (mz + t * dz) * ez;
        return h >= 0 && h <= ee ? t : Double.POSITIVE_INFINITY;
    }
}
