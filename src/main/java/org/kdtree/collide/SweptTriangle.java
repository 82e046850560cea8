package org.kdtree.collide;

/**
 * The face of a 3-D triangle as something a sphere can hit: the closest point of the (closed)
 * triangle to a point, and the first contact of a moving sphere with the face's interior, which is
 * the moment the centre reaches one of the two planes at distance r from the triangle's plane
 * while projecting inside the triangle. Edges and vertices are {@link SweptSegment}'s and
 * {@link SweptPoint}'s.
 *
 * <p>Corners are read from a flat array, nine doubles per triangle from offset {@code b}. With
 * {@code n = (B - A) x (C - A)}, a point p projects inside the triangle when the three triple
 * products {@code ((B - A) x (p - A)) . n} etc. are all >= 0 (closed, so a projection exactly on an
 * edge is inside); the component of p along n drops out, so p need not be projected first.
 */
final class SweptTriangle {
    private SweptTriangle() {
    }

    /**
     * Writes the point of the triangle closest to p into {@code out[0..3)} (unless {@code out} is
     * null) and returns the squared distance. The triangle must have non-zero area.
     */
    static double closestPoint(double[] c, int b, double x, double y, double z, double[] out) {
        double ax = c[b], ay = c[b + 1], az = c[b + 2];
        double e1x = c[b + 3] - ax, e1y = c[b + 4] - ay, e1z = c[b + 5] - az;
        double e2x = c[b + 6] - ax, e2y = c[b + 7] - ay, e2z = c[b + 8] - az;
        double nx = e1y * e2z - e1z * e2y, ny = e1z * e2x - e1x * e2z, nz = e1x * e2y - e1y * e2x;
        if (projectsInside(c, b, nx, ny, nz, x, y, z)) {
            // The closest point is p's projection onto the plane.
            double nn = nx * nx + ny * ny + nz * nz, h = nx * (x - ax) + ny * (y - ay) + nz * (z - az);
            double k = h / nn;
            if (out != null) { out[0] = x - k * nx; out[1] = y - k * ny; out[2] = z - k * nz; }
            return h * k;
        }
        // Otherwise it lies on the boundary: the closest of the three edges.
        int best = 0;
        double bestD = Double.POSITIVE_INFINITY;
        for (int e = 0; e < 3; e++) {
            int p = b + 3 * e, q = b + 3 * ((e + 1) % 3);
            double d = SweptSegment.closestPoint(c[p], c[p + 1], c[p + 2], c[q], c[q + 1], c[q + 2], x, y, z, null);
            if (d < bestD) { bestD = d; best = e; }
        }
        if (out == null) return bestD;
        int p = b + 3 * best, q = b + 3 * ((best + 1) % 3);
        return SweptSegment.closestPoint(c[p], c[p + 1], c[p + 2], c[q], c[q + 1], c[q + 2], x, y, z, out);
    }

    /**
     * The smallest t in [0, tMax] at which the centre {@code s + t d} reaches distance r from the
     * plane while projecting inside the triangle, or +infinity. Precondition: the sphere does not
     * touch the triangle at t = 0. A path parallel to the face never reaches it through the face;
     * a path starting between the two offset planes can only come in over an edge (the edges'
     * cylinders contain the prism's side walls).
     */
    static double firstContact(double[] c, int b, double sx, double sy, double sz, double dx, double dy, double dz,
                               double r, double tMax) {
        double ax = c[b], ay = c[b + 1], az = c[b + 2];
        double e1x = c[b + 3] - ax, e1y = c[b + 4] - ay, e1z = c[b + 5] - az;
        double e2x = c[b + 6] - ax, e2y = c[b + 7] - ay, e2z = c[b + 8] - az;
        double nx = e1y * e2z - e1z * e2y, ny = e1z * e2x - e1x * e2z, nz = e1x * e2y - e1y * e2x;
        // Distances along n are scaled by |n|: the one square root of the test.
        double rn = r * Math.sqrt(nx * nx + ny * ny + nz * nz);
        double h0 = nx * (sx - ax) + ny * (sy - ay) + nz * (sz - az), dn = nx * dx + ny * dy + nz * dz;
        double t;
        if (h0 > rn && dn < 0) t = (h0 - rn) / -dn;
        else if (h0 < -rn && dn > 0) t = (-rn - h0) / dn;
        else return Double.POSITIVE_INFINITY;
        if (!(t <= tMax)) return Double.POSITIVE_INFINITY;
        return projectsInside(c, b, nx, ny, nz, sx + t * dx, sy + t * dy, sz + t * dz) ? t : Double.POSITIVE_INFINITY;
    }

    /** Whether p projects into the closed triangle (three triple products >= 0). */
    static boolean projectsInside(double[] c, int b, double nx, double ny, double nz, double x, double y, double z) {
        return side(c, b, b + 3, nx, ny, nz, x, y, z) >= 0
                && side(c, b + 3, b + 6, nx, ny, nz, x, y, z) >= 0
                && side(c, b + 6, b, nx, ny, nz, x, y, z) >= 0;
    }

    /** {@code ((Q - P) x (p - P)) . n} for the edge P = c[i..], Q = c[j..]: >= 0 on the inner side. */
    private static double side(double[] c, int i, int j, double nx, double ny, double nz, double x, double y, double z) {
        double ex = c[j] - c[i], ey = c[j + 1] - c[i + 1], ez = c[j + 2] - c[i + 2];
        double px = x - c[i], py = y - c[i + 1], pz = z - c[i + 2];
        return (ey * pz - ez * py) * nx + (ez * px - ex * pz) * ny + (ex * py - ey * px) * nz;
    }
}
