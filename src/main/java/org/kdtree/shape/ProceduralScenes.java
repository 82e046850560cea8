package org.kdtree.shape;

import java.util.Random;

/**
 * Generated triangle scenes for benchmarks and tests, so that no measurement needs a file:
 * uniform random triangles, clustered triangles, a closed bumpy surface shaped like a scanned
 * mesh, and the grid of copies of a mesh that the benchmark spec uses for scaling runs.
 */
public final class ProceduralScenes {
    private ProceduralScenes() {
    }

    /** {@code n} random triangles with corners up to {@code size} from a uniform centre in the unit cube. */
    public static TriangleMesh uniform(int n, double size, long seed) {
        Random r = new Random(seed);
        double[] v = new double[9 * n];
        for (int t = 0; t < n; t++) {
            double cx = r.nextDouble(), cy = r.nextDouble(), cz = r.nextDouble();
            for (int c = 0; c < 3; c++) {
                v[9 * t + 3 * c] = cx + size * (r.nextDouble() - 0.5);
                v[9 * t + 3 * c + 1] = cy + size * (r.nextDouble() - 0.5);
                v[9 * t + 3 * c + 2] = cz + size * (r.nextDouble() - 0.5);
            }
        }
        return new TriangleMesh(v, sequence(3 * n));
    }

    /** {@code n} random triangles of a size that keeps the scene's density alike for every n. */
    public static TriangleMesh uniform(int n, long seed) {
        return uniform(n, 2.0 / Math.cbrt(n), seed);
    }

    /** {@code n} small triangles in five tight Gaussian clusters, every 50th one large. */
    public static TriangleMesh clustered(int n, long seed) {
        Random r = new Random(seed);
        double[][] centers = new double[5][3];
        for (double[] c : centers) for (int a = 0; a < 3; a++) c[a] = r.nextDouble() * 10;
        double small = 0.5 / Math.cbrt(n);
        double[] v = new double[9 * n];
        for (int t = 0; t < n; t++) {
            double[] c = centers[r.nextInt(centers.length)];
            double s = t % 50 == 0 ? 3 : small;
            double px = c[0] + 0.3 * r.nextGaussian(), py = c[1] + 0.3 * r.nextGaussian(), pz = c[2] + 0.3 * r.nextGaussian();
            for (int k = 0; k < 3; k++) {
                v[9 * t + 3 * k] = px + s * r.nextDouble();
                v[9 * t + 3 * k + 1] = py + s * r.nextDouble();
                v[9 * t + 3 * k + 2] = pz + s * r.nextDouble();
            }
        }
        return new TriangleMesh(v, sequence(3 * n));
    }

    /**
     * A closed, bumpy, mesh-like surface: a sphere of {@code rings x segments} quads (two
     * triangles each, shared vertices, as a scanned mesh has) with radial waves and noise.
     */
    public static TriangleMesh surface(int rings, int segments, long seed) {
        Random r = new Random(seed);
        int nv = (rings + 1) * segments;
        double[] v = new double[3 * nv];
        for (int i = 0; i <= rings; i++) {
            double theta = Math.PI * i / rings;
            for (int j = 0; j < segments; j++) {
                double phi = 2 * Math.PI * j / segments;
                double rad = 1 + 0.05 * Math.sin(5 * theta) * Math.cos(7 * phi) + 0.01 * r.nextDouble();
                int at = 3 * (i * segments + j);
                v[at] = rad * Math.sin(theta) * Math.cos(phi);
                v[at + 1] = rad * Math.cos(theta);
                v[at + 2] = rad * Math.sin(theta) * Math.sin(phi);
            }
        }
        int[] idx = new int[6 * rings * segments];
        int m = 0;
        for (int i = 0; i < rings; i++) {
            for (int j = 0; j < segments; j++) {
                int a = i * segments + j, b = i * segments + (j + 1) % segments, c = a + segments, d = b + segments;
                idx[m++] = a; idx[m++] = c; idx[m++] = b;
                idx[m++] = b; idx[m++] = c; idx[m++] = d;
            }
        }
        return new TriangleMesh(v, idx);
    }

    /** A mesh-like surface of about {@code n} triangles (rings : segments = 1 : 2). */
    public static TriangleMesh surface(int n, long seed) {
        int rings = Math.max(2, (int) Math.round(Math.sqrt(n / 4.0)));
        return surface(rings, Math.max(3, n / (2 * rings)), seed);
    }

    /**
     * The mesh repeated {@code g x g} times on the x-z plane, copy (gx, gz) offset by
     * (1.1 gx extent.x, 0, 1.1 gz extent.z): the spec's scaling scene (g = 4: the bunny grid).
     */
    public static TriangleMesh grid(TriangleMesh mesh, int g) {
        double[] v = mesh.vertices();
        int[] idx = mesh.indices();
        double[] lo = {Double.POSITIVE_INFINITY, 0, Double.POSITIVE_INFINITY}, hi = {Double.NEGATIVE_INFINITY, 0, Double.NEGATIVE_INFINITY};
        for (int i = 0; i < v.length; i += 3) {
            lo[0] = Math.min(lo[0], v[i]); hi[0] = Math.max(hi[0], v[i]);
            lo[2] = Math.min(lo[2], v[i + 2]); hi[2] = Math.max(hi[2], v[i + 2]);
        }
        double ex = hi[0] - lo[0], ez = hi[2] - lo[2];
        int nv = v.length / 3, copies = g * g;
        double[] gv = new double[v.length * copies];
        int[] gi = new int[idx.length * copies];
        int c = 0;
        for (int gx = 0; gx < g; gx++)
            for (int gz = 0; gz < g; gz++, c++) {
                double ox = 1.1 * gx * ex, oz = 1.1 * gz * ez;
                for (int i = 0; i < v.length; i += 3) {
                    gv[c * v.length + i] = v[i] + ox;
                    gv[c * v.length + i + 1] = v[i + 1];
                    gv[c * v.length + i + 2] = v[i + 2] + oz;
                }
                for (int i = 0; i < idx.length; i++) gi[c * idx.length + i] = idx[i] + c * nv;
            }
        return new TriangleMesh(gv, gi);
    }

    private static int[] sequence(int n) {
        int[] s = new int[n];
        for (int i = 0; i < n; i++) s[i] = i;
        return s;
    }
}
