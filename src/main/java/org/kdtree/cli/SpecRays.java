package org.kdtree.cli;

import org.kdtree.geom.Box;

/**
 * The benchmark's ray sets (bench SPEC), held in flat arrays so that they are generated before
 * timing: set P, 1024 x 1024 primary rays from the eye (pixel (i, j) is ray {@code j * 1024 + i}),
 * and set R, 1,000,000 random rays with origins in the scene box, from splitmix64 seeded 42.
 */
public final class SpecRays {
    /** Width and height of set P's image. */
    public static final int IMAGE = 1024;
    /** Rays in set R. */
    public static final int RANDOM_RAYS = 1_000_000;

    /** x, y, z per ray. */
    public final double[] origins, directions;

    private SpecRays(int n) {
        origins = new double[3 * n];
        directions = new double[3 * n];
    }

    public int size() { return origins.length / 3; }

    /** Set P for a scene with bounds {@code box}. */
    public static SpecRays primary(Box box) {
        double[] c = new double[3], eye = new double[3];
        double d = diagonal(box);
        double[] w = {1, 0.5, 2};
        double wl = Math.sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
        for (int a = 0; a < 3; a++) {
            c[a] = (box.min(a) + box.max(a)) / 2;
            eye[a] = c[a] + (1.5 * d) * (w[a] / wl);
        }
        double[] forward = normalize(new double[] {c[0] - eye[0], c[1] - eye[1], c[2] - eye[2]});
        double[] right = normalize(cross(forward, new double[] {0, 1, 0}));
        double[] up2 = cross(right, forward);
        double s = Math.tan(Math.toRadians(20));
        SpecRays rays = new SpecRays(IMAGE * IMAGE);
        double[] dir = new double[3];
        for (int j = 0; j < IMAGE; j++) {
            for (int i = 0; i < IMAGE; i++) {
                double x = (2 * (i + 0.5) / IMAGE - 1) * s, y = (1 - 2 * (j + 0.5) / IMAGE) * s;
                for (int a = 0; a < 3; a++) dir[a] = forward[a] + x * right[a] + y * up2[a];
                normalize(dir);
                int r = 3 * (j * IMAGE + i);
                System.arraycopy(eye, 0, rays.origins, r, 3);
                System.arraycopy(dir, 0, rays.directions, r, 3);
            }
        }
        return rays;
    }

    /** Set R for a scene with bounds {@code box}. */
    public static SpecRays random(Box box) {
        SplitMix64 rng = new SplitMix64(42);
        SpecRays rays = new SpecRays(RANDOM_RAYS);
        for (int n = 0; n < RANDOM_RAYS; n++) {
            double ux = rng.nextDouble(), uy = rng.nextDouble(), uz = rng.nextDouble();
            double u = rng.nextDouble(), v = rng.nextDouble();
            double[] uo = {ux, uy, uz};
            for (int a = 0; a < 3; a++) rays.origins[3 * n + a] = box.min(a) + uo[a] * (box.max(a) - box.min(a));
            double zc = 1 - 2 * u, phi = 2 * Math.PI * v, r = Math.sqrt(Math.max(0, 1 - zc * zc));
            rays.directions[3 * n] = r * Math.cos(phi);
            rays.directions[3 * n + 1] = r * Math.sin(phi);
            rays.directions[3 * n + 2] = zc;
        }
        return rays;
    }

    /** |max - min|, the bounding box diagonal. */
    static double diagonal(Box box) {
        double s = 0;
        for (int a = 0; a < 3; a++) s += box.extent(a) * box.extent(a);
        return Math.sqrt(s);
    }

    private static double[] normalize(double[] v) {
        double l = Math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        for (int a = 0; a < 3; a++) v[a] /= l;
        return v;
    }

    private static double[] cross(double[] a, double[] b) {
        return new double[] {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }
}
