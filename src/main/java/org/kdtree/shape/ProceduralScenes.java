package org.kdtree.shape;

import java.util.Random;
import org.kdtree.geom.Box;
import org.kdtree.limits.Limits;

/**
 * Generated triangle scenes for benchmarks and tests, so that no measurement needs a file:
 * uniform random triangles, clustered triangles, a closed bumpy surface shaped like a scanned
 * mesh, and the grid of copies of a mesh that the benchmark spec uses for scaling runs.
 */
public final class ProceduralScenes {
    private ProceduralScenes() {
    }

    /**
     * {@code n} random triangles with corners up to {@code size} from a uniform centre in the unit cube.
     *
     * @param n the number of triangles
     * @param size the largest corner offset from a triangle's centre
     * @param seed the random seed
     * @return the mesh
     */
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

    /**
     * {@code n} random triangles of a size that keeps the scene's density alike for every n.
     *
     * @param n the number of triangles
     * @param seed the random seed
     * @return the mesh
     */
    public static TriangleMesh uniform(int n, long seed) {
        return uniform(n, 2.0 / Math.cbrt(n), seed);
    }

    /**
     * {@code n} small triangles in five tight Gaussian clusters, every 50th one large.
     *
     * @param n the number of triangles
     * @param seed the random seed
     * @return the mesh
     */
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
     * @param rings the number of rings, pole to pole
     * @param segments the number of segments around
     * @param seed the random seed
     * @return the mesh
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

    /**
     * A mesh-like surface of about {@code n} triangles (rings : segments = 1 : 2).
     *
     * @param n the approximate number of triangles
     * @param seed the random seed
     * @return the mesh
     */
    public static TriangleMesh surface(int n, long seed) {
        int rings = Math.max(2, (int) Math.round(Math.sqrt(n / 4.0)));
        return surface(rings, Math.max(3, n / (2 * rings)), seed);
    }

    /**
     * The benchmark's scaling scene (the spec's meshes README): the mesh repeated in a g x g grid
     * on the x-z plane, copy (gx, gz) offset by (1.1 gx extent.x, 0, 1.1 gz extent.z), the
     * extent taken over all vertices. Copies are numbered gx-major ({@code copy = gx * g + gz});
     * triangle t of copy c becomes {@code c * T + t}, T the mesh's triangle count.
     * @param mesh the mesh to repeat
     * @param g copies along x and along z
     * @return the grid of {@code g * g} copies ({@code mesh} itself when g is 1)
     */
    public static TriangleMesh grid(TriangleMesh mesh, int g) {
        Limits.GRID.check("grid", g);
        if (g == 1) return mesh;
        long triangles = (long) mesh.size() * g * g, limit = 1 << 28;
        if (triangles > limit || (long) mesh.vertexCount() * g * g > limit)
            throw new IllegalArgumentException(String.format(java.util.Locale.ROOT,
                    "a %d x %d grid of %,d triangles would hold %,d; at most %,d fit", g, g, mesh.size(), triangles, limit));
        double[] v = mesh.vertices();
        int[] f = mesh.indices();
        Box box = vertexBounds(mesh);
        int nv = v.length / 3;
        double[] vs = new double[v.length * g * g];
        int[] fs = new int[f.length * g * g];
        for (int gx = 0; gx < g; gx++) {
            for (int gz = 0; gz < g; gz++) {
                int copy = gx * g + gz;
                double ox = 1.1 * gx * box.extent(0), oz = 1.1 * gz * box.extent(2);
                for (int i = 0; i < nv; i++) {
                    int d = copy * v.length + 3 * i;
                    vs[d] = v[3 * i] + ox;
                    vs[d + 1] = v[3 * i + 1];
                    vs[d + 2] = v[3 * i + 2] + oz;
                }
                for (int i = 0; i < f.length; i++) fs[copy * f.length + i] = f[i] + copy * nv;
            }
        }
        return new TriangleMesh(vs, fs);
    }

    /**
     * The spec's bounding box: min/max over all vertices, referenced by a triangle or not.
     *
     * @param mesh the mesh
     * @return its vertex bounds
     */
    public static Box vertexBounds(TriangleMesh mesh) {
        Box b = new Box(3);
        double[] v = mesh.vertices();
        for (int i = 0; i < v.length; i += 3) b.grow(v, i);
        return b;
    }

    private static int[] sequence(int n) {
        int[] s = new int[n];
        for (int i = 0; i < n; i++) s[i] = i;
        return s;
    }
}
