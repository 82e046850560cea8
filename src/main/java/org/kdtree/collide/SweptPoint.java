package org.kdtree.collide;

/**
 * A vertex, or a 2-D point, as something a sphere can hit: the sphere's centre moving along
 * {@code s + t d} touches the point {@code v} when {@code |s + t d - v| <= r}, so the first contact
 * is a ray against the sphere of radius r around v. In 2-D pass z = 0 for everything: the same
 * equations then describe a circle.
 */
final class SweptPoint {
    private SweptPoint() {
    }

    /** Squared distance from p to v. */
    static double distanceSquared(double vx, double vy, double vz, double px, double py, double pz) {
        double x = px - vx, y = py - vy, z = pz - vz;
        return x * x + y * y + z * z;
    }

    /**
     * The smallest t in [0, tMax] with {@code |s + t d - v| <= r}, or +infinity. A tangent path
     * (discriminant exactly zero) touches: contacts are closed.
     */
    static double firstContact(double vx, double vy, double vz, double sx, double sy, double sz,
                               double dx, double dy, double dz, double r, double tMax) {
        double mx = sx - vx, my = sy - vy, mz = sz - vz;
        double c = mx * mx + my * my + mz * mz - r * r;
        if (c <= 0) return 0; // already touching
        double b = mx * dx + my * dy + mz * dz;
        if (b >= 0) return Double.POSITIVE_INFINITY; // moving away, or not moving
        double a = dx * dx + dy * dy + dz * dz;
        // b^2 - a c, rewritten by Lagrange's identity as a r^2 - |m x d|^2: the expanded form
        // cancels catastrophically when the path passes far from v compared with r (and for r = 0).
        double cx = my * dz - mz * dy, cy = mz * dx - mx * dz, cz = mx * dy - my * dx;
        double disc = a * r * r - (cx * cx + cy * cy + cz * cz);
        if (disc < 0) return Double.POSITIVE_INFINITY;
        // The smaller root of a t^2 + 2 b t + c, written c / (-b + sqrt) so that nothing cancels (b < 0).
        double t = c / (-b + Math.sqrt(disc));
        return t <= tMax ? t : Double.POSITIVE_INFINITY;
    }
}
