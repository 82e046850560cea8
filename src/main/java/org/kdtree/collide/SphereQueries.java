package org.kdtree.collide;

import org.kdtree.geom.Tolerance;

/** Argument checks and the voxel padding shared by the sphere queries. */
final class SphereQueries {
    private SphereQueries() {
    }

    static void checkPoint(String what, double[] p, int k) {
        if (p.length < k) throw new IllegalArgumentException(what + " has " + p.length + " coordinates, the scene " + k);
        for (int a = 0; a < k; a++)
            if (!(Math.abs(p[a]) <= Tolerance.MAX_COORDINATE))   // also NaN and infinities
                throw new IllegalArgumentException(what + " has the coordinate " + p[a]
                        + ": the supported range is -1e100 .. 1e100 (squared distances would overflow)");
    }

    static void checkRadius(double r) {
        if (!(r >= 0 && r <= Tolerance.MAX_COORDINATE))
            throw new IllegalArgumentException("radius must be between 0 and 1e100, got " + r);
    }

    /** {@link Tolerance#VOXEL_PAD} times the largest magnitude involved. */
    static double pad(double sceneScale, double[] s, double[] d, double r, int k) {
        double m = sceneScale + r;
        for (int a = 0; a < k; a++) m = Math.max(m, Math.abs(s[a]) + (d == null ? 0 : Math.abs(d[a])));
        return m * Tolerance.VOXEL_PAD;
    }
}
