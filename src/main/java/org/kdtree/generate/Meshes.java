package org.kdtree.generate;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.kdtree.shape.TriangleMesh;

/**
 * Generated 3-D triangle scenes, so that no measurement or test needs a file: uniform and
 * clustered triangle soups, the contract's corner clusters and flat scene, a closed bumpy surface
 * shaped like a scanned mesh, planar and degenerate cases. The benchmarks name three of them
 * ({@link #named}); the hard inputs built without randomness are {@link HardMeshes}.
 */
public final class Meshes {
    private Meshes() {
    }

    /**
     * The benchmarks' scenes by name, each with its own fixed seed.
     *
     * @param name {@code uniform} (seed 1), {@code clustered} (seed 2) or {@code surface} (seed 3)
     * @param n the number of triangles (about n for the surface)
     * @return the mesh
     * @throws IllegalArgumentException for another name
     */
    public static TriangleMesh named(String name, int n) {
        return switch (name) {
            case "uniform" -> uniform(n, 1);
            case "clustered" -> clustered(n, 2);
            case "surface" -> surface(n, 3);
            default -> throw new IllegalArgumentException("no generated scene '" + name + "' (uniform, clustered, surface)");
        };
    }

    /**
     * {@code n} triangles with corners up to {@code size} from a uniform centre in the unit cube.
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
        return soup(v);
    }

    /**
     * {@link #uniform(int, double, long)} with triangles of a size that keeps the density alike for every n.
     *
     * @param n the number of triangles
     * @param seed the random seed
     * @return the mesh
     */
    public static TriangleMesh uniform(int n, long seed) {
        return uniform(n, 2.0 / Math.cbrt(n), seed);
    }

    /**
     * {@code n} small triangles in five tight clusters ({@code Clusters}: standard deviation 0.3,
     * centres in [0, 10]^3, each triangle's cluster drawn at random), every 50th triangle large
     * (corners up to 3 from its anchor).
     *
     * @param n the number of triangles
     * @param size the largest corner offset of a small triangle from its anchor
     * @param seed the random seed
     * @return the mesh
     */
    public static TriangleMesh clustered(int n, double size, long seed) {
        Random r = new Random(seed);
        Clusters clusters = Clusters.draw(r, 5, 3, 0, 10);
        double[] v = new double[9 * n], anchor = new double[3];
        for (int t = 0; t < n; t++) {
            clusters.member(r, clusters.pick(r), 0.3, anchor, 0);
            double s = t % 50 == 0 ? 3 : size;
            for (int k = 0; k < 3; k++)
                for (int a = 0; a < 3; a++) v[9 * t + 3 * k + a] = anchor[a] + s * r.nextDouble();
        }
        return soup(v);
    }

    /**
     * {@link #clustered(int, double, long)} with small triangles of a size that keeps the density alike for every n.
     *
     * @param n the number of triangles
     * @param seed the random seed
     * @return the mesh
     */
    public static TriangleMesh clustered(int n, long seed) {
        return clustered(n, 0.5 / Math.cbrt(n), seed);
    }

    /**
     * {@code n} tiny triangles in three tight clusters at fixed corners of the unit cube, taken in
     * turn, and two tinier ones at opposite corners stretching the scene box: mostly empty space.
     *
     * @param n the number of triangles in the clusters
     * @param seed the random seed
     * @return the triangle soup of {@code n + 2} triangles
     */
    public static TriangleMesh cornerClusters(int n, long seed) {
        Random r = new Random(seed);
        double[][] centres = {{0.05, 0.05, 0.05}, {0.95, 0.1, 0.9}, {0.5, 0.95, 0.1}};
        double[] v = new double[9 * (n + 2)];
        for (int t = 0; t < n; t++) {
            double[] c = centres[t % 3];
            for (int k = 0; k < 3; k++) {
                double base = c[k] + r.nextGaussian() * 0.01;
                for (int corner = 0; corner < 3; corner++)
                    v[9 * t + 3 * corner + k] = base + (corner == 0 ? 0 : r.nextGaussian() * 0.005);
            }
        }
        double[] far = {0, 0, 0, 0.001, 0, 0, 0, 0.001, 0, 1, 1, 1, 0.999, 1, 1, 1, 0.999, 1};
        System.arraycopy(far, 0, v, 9 * n, 18);
        return soup(v);
    }

    /**
     * A flat scene: {@link #uniform(int, double, long) uniform} triangles of size 0.05, all moved into the plane z = 0.5.
     *
     * @param n the number of triangles
     * @param seed the random seed
     * @return the triangle soup
     */
    public static TriangleMesh flat(int n, long seed) {
        double[] v = uniform(n, 0.05, seed).vertices();
        for (int i = 2; i < v.length; i += 3) v[i] = 0.5;
        return soup(v);
    }

    /**
     * A closed, bumpy, mesh-like surface: a sphere of {@code rings x segments} quads (two
     * triangles each, shared vertices, as a scanned mesh has) with radial waves and noise.
     *
     * @param rings the number of rings, pole to pole
     * @param segments the number of segments around
     * @param seed the random seed
     * @return the mesh
     */
    public static TriangleMesh surface(int rings, int segments, long seed) {
        Random r = new Random(seed);
        double[] v = new double[3 * (rings + 1) * segments];
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
     * A mesh-like {@link #surface(int, int, long) surface} of about {@code n} triangles (rings : segments = 1 : 2).
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
     * Planar and degenerate cases together: axis-aligned triangles in shared planes (four floors
     * of a 6 x 6 grid), walls in planes x = const each with a coincident duplicate, zero-area
     * slivers and point triangles, and ordinary triangles crossing the planes.
     *
     * @param seed the random seed
     * @return the triangle soup
     */
    public static TriangleMesh planarAndDegenerate(long seed) {
        Random r = new Random(seed);
        List<double[]> tris = new ArrayList<>();
        for (int f = 0; f < 4; f++) {
            double z = f * 0.25, d = 1 / 6.0;
            for (int i = 0; i < 6; i++)
                for (int j = 0; j < 6; j++) {
                    double x = i / 6.0, y = j / 6.0;
                    tris.add(new double[] {x, y, z, x + d, y, z, x, y + d, z});
                    tris.add(new double[] {x + d, y, z, x + d, y + d, z, x, y + d, z});
                }
        }
        for (int i = 0; i < 10; i++) {
            double x = r.nextInt(4) * 0.25;
            double[] w = {x, 0.1, 0.1, x, 0.6, 0.2, x, 0.3, 0.7};
            tris.add(w);
            tris.add(w.clone());
        }
        for (int i = 0; i < 20; i++) {
            double x = r.nextDouble(), y = r.nextDouble(), z = r.nextDouble();
            tris.add(new double[] {x, y, z, x + 0.1, y + 0.1, z, x + 0.2, y + 0.2, z});
            tris.add(new double[] {x, y, z, x, y, z, x, y, z});
        }
        for (int i = 0; i < 30; i++) {
            double x = r.nextDouble(), y = r.nextDouble(), z = r.nextDouble();
            tris.add(new double[] {x, y, z, x + 0.3, y, z + 0.2, x, y + 0.3, z - 0.2});
        }
        return HardMeshes.soup(tris);
    }

    private static TriangleMesh soup(double[] coords) {
        return HardMeshes.soup(coords);
    }
}
