package org.kdtree.check;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import org.kdtree.io.BundledScenes;
import org.kdtree.io.Scene2DReader;
import org.kdtree.shape.Scene2D;
import org.kdtree.shape.Shape2D;
import org.kdtree.shape.TriangleMesh;

/**
 * The scenes the builder contract checks on, generated in code (seeded, so every run sees the
 * same ones): ordinary 2-D and 3-D scenes and the hard inputs. The library's own tests use them
 * too ({@code testing.TestScenes}).
 */
public class ContractScenes {
    /** Static methods only; subclassed by the tests' {@code TestScenes}. */
    protected ContractScenes() {
    }

    /** {@return the handful of 2-D objects of the bundled scenes/talk-figures.scene2d, like the talk's figures 2-5} */
    public static Scene2D talkFigures() {
        try {
            return Scene2DReader.read(BundledScenes.path("talk-figures.scene2d"));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /**
     * n random 2-D shapes of every kind in [0, 100]^2.
     * @param n the number of shapes
     * @param seed the random seed
     * @return the shapes
     */
    public static Scene2D random2D(int n, long seed) {
        Random r = new Random(seed);
        List<Shape2D> shapes = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            double x = r.nextDouble() * 100, y = r.nextDouble() * 100, s = 0.5 + r.nextDouble() * 8;
            shapes.add(switch (i % 4) {
                case 0 -> new Shape2D.Point(x, y);
                case 1 -> new Shape2D.Segment(x, y, x + r.nextGaussian() * s, y + r.nextGaussian() * s);
                case 2 -> new Shape2D.Rect(x, y, x + r.nextDouble() * s, y + r.nextDouble() * s);
                default -> new Shape2D.Triangle(x, y, x + r.nextGaussian() * s, y + r.nextGaussian() * s,
                        x + r.nextGaussian() * s, y + r.nextGaussian() * s);
            });
        }
        return new Scene2D(shapes);
    }

    /**
     * n small 2-D triangles in a few tight clusters inside a large empty square.
     * @param n the number of triangles
     * @param seed the random seed
     * @return the shapes
     */
    public static Scene2D clustered2D(int n, long seed) {
        Random r = new Random(seed);
        double[][] centres = {{10, 10}, {85, 20}, {40, 90}};
        List<Shape2D> shapes = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            double[] c = centres[i % centres.length];
            double x = c[0] + r.nextGaussian() * 2, y = c[1] + r.nextGaussian() * 2;
            shapes.add(new Shape2D.Triangle(x, y, x + 0.3, y, x, y + 0.3));
        }
        shapes.add(new Shape2D.Point(0, 0));
        shapes.add(new Shape2D.Point(100, 100));
        return new Scene2D(shapes);
    }

    /**
     * n random triangles of size about {@code size} in [0, 1]^3.
     * @param n the number of triangles
     * @param size their typical edge length
     * @param seed the random seed
     * @return the triangle soup
     */
    public static TriangleMesh randomTriangles(int n, double size, long seed) {
        Random r = new Random(seed);
        double[] v = new double[9 * n];
        for (int t = 0; t < n; t++) {
            double x = r.nextDouble(), y = r.nextDouble(), z = r.nextDouble();
            for (int c = 0; c < 3; c++) {
                v[9 * t + 3 * c] = x + (c == 0 ? 0 : r.nextGaussian() * size);
                v[9 * t + 3 * c + 1] = y + (c == 0 ? 0 : r.nextGaussian() * size);
                v[9 * t + 3 * c + 2] = z + (c == 0 ? 0 : r.nextGaussian() * size);
            }
        }
        return soup(v);
    }

    /**
     * n small triangles in three tight clusters at corners of a large box.
     * @param n the number of triangles
     * @param seed the random seed
     * @return the triangle soup
     */
    public static TriangleMesh clusteredTriangles(int n, long seed) {
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
        // two tiny triangles at opposite corners stretch the scene box
        double[] far = {0, 0, 0, 0.001, 0, 0, 0, 0.001, 0, 1, 1, 1, 0.999, 1, 1, 1, 0.999, 1};
        System.arraycopy(far, 0, v, 9 * n, 18);
        return soup(v);
    }

    /**
     * A flat scene: random triangles all in the plane z = 0.5.
     * @param n the number of triangles
     * @param seed the random seed
     * @return the triangle soup
     */
    public static TriangleMesh flatTriangles(int n, long seed) {
        TriangleMesh m = randomTriangles(n, 0.05, seed);
        double[] v = m.vertices().clone();
        for (int i = 2; i < v.length; i += 3) v[i] = 0.5;
        return new TriangleMesh(v, m.indices());
    }

    /**
     * {@code copies} copies of one triangle.
     * @param copies how many
     * @return the mesh
     */
    public static TriangleMesh identicalTriangles(int copies) {
        double[] v = {0, 0, 0, 1, 0, 0, 0, 1, 0.5};
        int[] idx = new int[3 * copies];
        for (int t = 0; t < copies; t++) {
            idx[3 * t] = 0;
            idx[3 * t + 1] = 1;
            idx[3 * t + 2] = 2;
        }
        return new TriangleMesh(v, idx);
    }

    /** {@return zero-area triangles (collinear, repeated vertex, all three equal) among ordinary ones} */
    public static TriangleMesh degenerateTriangles() {
        double[] v = {
                0, 0, 0, 1, 1, 1, 2, 2, 2,          // collinear
                0.5, 0, 0, 0.5, 0, 0, 1, 1, 0,      // repeated vertex
                0.3, 0.3, 0.3, 0.3, 0.3, 0.3, 0.3, 0.3, 0.3, // a point
                0, 2, 0, 2, 2, 0, 0, 2, 2,          // ordinary
                1, 0, 2, 2, 0, 2, 2, 1, 2,          // ordinary
        };
        return soup(v);
    }

    /**
     * An n x n x n grid of unit cubes (12 triangles each, gap between cubes): every face lies in
     * a plane the SAH will consider, so planar triangles and faces in split planes are everywhere.
     * @param n the cubes per axis
     * @return the triangle soup
     */
    public static TriangleMesh cubeGrid(int n) {
        List<double[]> tris = new ArrayList<>();
        for (int i = 0; i < n; i++)
            for (int j = 0; j < n; j++)
                for (int k = 0; k < n; k++) addCube(tris, 2 * i, 2 * j, 2 * k, 1);
        double[] v = new double[9 * tris.size()];
        for (int t = 0; t < tris.size(); t++) System.arraycopy(tris.get(t), 0, v, 9 * t, 9);
        return soup(v);
    }

    /**
     * Adds the 12 triangles of an axis-aligned cube with corner (x, y, z) and side s.
     * @param out receives 9 coordinates per triangle
     * @param x the corner's x
     * @param y the corner's y
     * @param z the corner's z
     * @param s the side
     */
    public static void addCube(List<double[]> out, double x, double y, double z, double s) {
        double[][] c = new double[8][];
        for (int i = 0; i < 8; i++) c[i] = new double[] {x + ((i & 1) != 0 ? s : 0), y + ((i & 2) != 0 ? s : 0), z + ((i & 4) != 0 ? s : 0)};
        int[][] quads = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
        for (int[] q : quads) {
            out.add(concat(c[q[0]], c[q[1]], c[q[2]]));
            out.add(concat(c[q[0]], c[q[2]], c[q[3]]));
        }
    }

    /**
     * Scales every coordinate of a mesh.
     * @param m the mesh
     * @param s the factor
     * @return the scaled copy
     */
    public static TriangleMesh scaled(TriangleMesh m, double s) {
        double[] v = m.vertices().clone();
        for (int i = 0; i < v.length; i++) v[i] *= s;
        return new TriangleMesh(v, m.indices());
    }

    /**
     * A triangle soup: 9 coordinates per triangle, each with its own three vertices.
     * @param coords 9 coordinates per triangle
     * @return the mesh
     */
    public static TriangleMesh soup(double[] coords) {
        int[] idx = new int[coords.length / 3];
        Arrays.setAll(idx, i -> i);
        return new TriangleMesh(coords, idx);
    }

    private static double[] concat(double[] a, double[] b, double[] c) {
        double[] r = new double[9];
        System.arraycopy(a, 0, r, 0, 3);
        System.arraycopy(b, 0, r, 3, 3);
        System.arraycopy(c, 0, r, 6, 3);
        return r;
    }
}
