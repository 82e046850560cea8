package org.kdtree.measure;

import org.kdtree.geom.Box;
import org.kdtree.generate.MeshGrid;
import org.kdtree.shape.TriangleMesh;

/**
 * A set of 3-D rays held in one flat array (origin then direction, six doubles per ray), so that
 * generating them is not timed with tracing. The sets of the benchmark spec
 * (docs/benchmark-spec.md): P, the primary rays of a 1024 x 1024 camera, and R, random rays
 * from origins inside the scene's box. The box is always the spec's: min and max over all the
 * mesh's vertices, used by a triangle or not ({@link MeshGrid#vertexBounds}).
 */
public final class RaySet {
    /** Width and height of the spec's set P image. */
    public static final int SPEC_IMAGE = 1024;
    /** Rays in the spec's set R. */
    public static final int SPEC_RANDOM_RAYS = 1_000_000;

    private final String name;
    private final double[] rays;
    private final int imageWidth;

    private RaySet(String name, double[] rays, int imageWidth) {
        this.name = name;
        this.rays = rays;
        this.imageWidth = imageWidth;
    }

    /**
     * {@return the width of the image whose pixels the rays are, row by row (set P), or 0 when they
     * are no image (set R)}: coherent rays, which {@link RayBatch} traces in tiles of packets
     */
    public int imageWidth() { return imageWidth; }

    /** {@return the set's name, "P" or "R"} */
    public String name() { return name; }

    /** {@return the number of rays} */
    public int size() { return rays.length / 6; }

    /** {@return a copy of the rays: origin and direction of ray {@code i} at {@code rays()[6 i .. 6 i + 6)}} */
    public double[] rays() { return rays.clone(); }

    /** The rays themselves, for this package's timed loops, which only read them. */
    double[] raw() { return rays; }

    /**
     * Set P: a {@code res x res} pinhole camera looking at the mesh's box from direction (1, 0.5, 2), 40 degrees.
     *
     * @param mesh the scene, whose vertex box the camera looks at
     * @param res  the image's width and height in pixels, one ray each
     * @return the {@code res * res} rays, row by row from the top, unit directions
     */
    public static RaySet primary(TriangleMesh mesh, int res) {
        return primary(MeshGrid.vertexBounds(mesh), res);
    }

    /**
     * Set R: {@code n} rays with uniform origins in the mesh's box and uniform directions (splitmix64, seed 42).
     *
     * @param mesh the scene, in whose vertex box the origins lie
     * @param n    how many rays
     * @return the rays, unit directions
     */
    public static RaySet random(TriangleMesh mesh, int n) {
        return random(MeshGrid.vertexBounds(mesh), n);
    }

    /**
     * Set P around a given box (the spec's formulas; the commands use {@link #primary(TriangleMesh, int)}, the spec's box).
     *
     * @param bounds the box the camera looks at
     * @param res    the image's width and height in pixels, one ray each
     * @return the {@code res * res} rays, row by row from the top, unit directions
     */
    public static RaySet primary(Box bounds, int res) {
        double[] c = new double[3];
        double d = 0;
        for (int a = 0; a < 3; a++) {
            c[a] = (bounds.min(a) + bounds.max(a)) / 2;
            d += bounds.extent(a) * bounds.extent(a);
        }
        d = Math.sqrt(d);
        double[] w = normalize(new double[] {1, 0.5, 2});
        double[] eye = {c[0] + 1.5 * d * w[0], c[1] + 1.5 * d * w[1], c[2] + 1.5 * d * w[2]};
        double[] fwd = normalize(new double[] {c[0] - eye[0], c[1] - eye[1], c[2] - eye[2]});
        double[] right = normalize(cross(fwd, new double[] {0, 1, 0}));
        double[] up = cross(right, fwd);
        double s = Math.tan(Math.toRadians(20));
        double[] r = new double[6 * res * res];
        int at = 0;
        for (int j = 0; j < res; j++) {
            double y = (1 - 2 * (j + 0.5) / res) * s;
            for (int i = 0; i < res; i++) {
                double x = (2 * (i + 0.5) / res - 1) * s;
                double[] dir = normalize(new double[] {fwd[0] + x * right[0] + y * up[0],
                        fwd[1] + x * right[1] + y * up[1], fwd[2] + x * right[2] + y * up[2]});
                r[at++] = eye[0]; r[at++] = eye[1]; r[at++] = eye[2];
                r[at++] = dir[0]; r[at++] = dir[1]; r[at++] = dir[2];
            }
        }
        return new RaySet("P", r, res);
    }

    /**
     * Set R in a given box (the spec's formulas; the commands use {@link #random(TriangleMesh, int)}, the spec's box).
     *
     * @param bounds the box where the origins lie
     * @param n      how many rays
     * @return the rays, unit directions
     */
    public static RaySet random(Box bounds, int n) {
        SplitMix64 rng = new SplitMix64(42);
        double[] r = new double[6 * n];
        for (int i = 0; i < n; i++) {
            double ux = rng.nextDouble(), uy = rng.nextDouble(), uz = rng.nextDouble();
            double u = rng.nextDouble(), v = rng.nextDouble();
            double zc = 1 - 2 * u, phi = 2 * Math.PI * v, rad = Math.sqrt(Math.max(0, 1 - zc * zc));
            r[6 * i] = bounds.min(0) + ux * bounds.extent(0);
            r[6 * i + 1] = bounds.min(1) + uy * bounds.extent(1);
            r[6 * i + 2] = bounds.min(2) + uz * bounds.extent(2);
            r[6 * i + 3] = rad * Math.cos(phi);
            r[6 * i + 4] = rad * Math.sin(phi);
            r[6 * i + 5] = zc;
        }
        return new RaySet("R", r, 0);
    }

    private static double[] normalize(double[] v) {
        double l = Math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        return new double[] {v[0] / l, v[1] / l, v[2] / l};
    }

    private static double[] cross(double[] a, double[] b) {
        return new double[] {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }
}
