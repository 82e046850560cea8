package org.kdtree.build;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.kdtree.shape.ProceduralScenes;
import org.kdtree.shape.Scene2D;
import org.kdtree.shape.Shape2D;
import org.kdtree.shape.TriangleMesh;

/** Small generated scenes for builder tests (no test may depend on files outside the project). */
final class Scenes {
    private Scenes() {
    }

    /** n random triangles of size up to {@code size} in the unit cube. */
    static TriangleMesh randomTriangles(int n, double size, long seed) {
        return ProceduralScenes.uniform(n, size, seed);
    }

    /** n small triangles in a few tight Gaussian clusters, plus a few large ones. */
    static TriangleMesh clustered(int n, long seed) {
        Random r = new Random(seed);
        double[][] centers = new double[5][3];
        for (double[] c : centers) for (int a = 0; a < 3; a++) c[a] = r.nextDouble() * 10;
        double[] v = new double[9 * n];
        int[] idx = new int[3 * n];
        for (int t = 0; t < n; t++) {
            double[] c = centers[r.nextInt(centers.length)];
            double s = t % 50 == 0 ? 3 : 0.02;
            double sigma = 0.3;
            double px = c[0] + sigma * r.nextGaussian(), py = c[1] + sigma * r.nextGaussian(), pz = c[2] + sigma * r.nextGaussian();
            for (int k = 0; k < 3; k++) {
                v[9 * t + 3 * k] = px + s * r.nextDouble();
                v[9 * t + 3 * k + 1] = py + s * r.nextDouble();
                v[9 * t + 3 * k + 2] = pz + s * r.nextDouble();
                idx[3 * t + k] = 3 * t + k;
            }
        }
        return new TriangleMesh(v, idx);
    }

    /**
     * A closed, bumpy, mesh-like surface: a sphere of {@code rings x segments} quads (two
     * triangles each) with radial noise, sharing vertices as a scanned mesh does.
     */
    static TriangleMesh bumpySphere(int rings, int segments, long seed) {
        return ProceduralScenes.surface(rings, segments, seed);
    }

    /**
     * Planar and degenerate cases: axis-aligned triangles lying in shared planes (a stack of
     * floors and walls on a grid), coincident duplicates, zero-area slivers and point triangles.
     */
    static TriangleMesh planarAndDegenerate(long seed) {
        Random r = new Random(seed);
        List<double[]> tris = new ArrayList<>();
        for (int f = 0; f < 4; f++) {
            double z = f * 0.25;
            for (int i = 0; i < 6; i++)
                for (int j = 0; j < 6; j++) {
                    double x = i / 6.0, y = j / 6.0, d = 1 / 6.0;
                    tris.add(new double[] {x, y, z, x + d, y, z, x, y + d, z});
                    tris.add(new double[] {x + d, y, z, x + d, y + d, z, x, y + d, z});
                }
        }
        for (int i = 0; i < 10; i++) {           // walls in planes x = const, two coincident each
            double x = r.nextInt(4) * 0.25;
            double[] w = {x, 0.1, 0.1, x, 0.6, 0.2, x, 0.3, 0.7};
            tris.add(w);
            tris.add(w.clone());
        }
        for (int i = 0; i < 20; i++) {           // zero-area slivers and points
            double x = r.nextDouble(), y = r.nextDouble(), z = r.nextDouble();
            tris.add(new double[] {x, y, z, x + 0.1, y + 0.1, z, x + 0.2, y + 0.2, z});
            tris.add(new double[] {x, y, z, x, y, z, x, y, z});
        }
        for (int i = 0; i < 30; i++) {           // ordinary triangles crossing the planes
            double x = r.nextDouble(), y = r.nextDouble(), z = r.nextDouble();
            tris.add(new double[] {x, y, z, x + 0.3, y, z + 0.2, x, y + 0.3, z - 0.2});
        }
        double[] v = new double[9 * tris.size()];
        int[] idx = new int[3 * tris.size()];
        for (int t = 0; t < tris.size(); t++) {
            System.arraycopy(tris.get(t), 0, v, 9 * t, 9);
            for (int c = 0; c < 3; c++) idx[3 * t + c] = 3 * t + c;
        }
        return new TriangleMesh(v, idx);
    }

    /** A random 2-D scene of triangles, segments (some axis-parallel), rectangles and points. */
    static Scene2D random2D(int n, long seed) {
        Random r = new Random(seed);
        List<Shape2D> s = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            double x = r.nextInt(40) / 4.0, y = r.nextDouble() * 10;
            switch (i % 5) {
                case 0 -> s.add(new Shape2D.Triangle(x, y, x + r.nextDouble(), y + r.nextDouble(), x - r.nextDouble(), y + 2 * r.nextDouble()));
                case 1 -> s.add(new Shape2D.Segment(x, y, x, y + r.nextDouble()));          // vertical: planar in x
                case 2 -> s.add(new Shape2D.Segment(x, y, x + 2 * r.nextDouble(), y + r.nextDouble()));
                case 3 -> s.add(new Shape2D.Rect(x, y, x + r.nextDouble(), y + r.nextDouble()));
                default -> s.add(new Shape2D.Point(x, Math.floor(y)));
            }
        }
        return new Scene2D(s);
    }
}
