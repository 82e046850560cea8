package org.kdtree.generate;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.kdtree.shape.Shape2D;
import org.kdtree.shape.Scene2D;

/**
 * Generated 2-D scenes. A scene of a name and a count is one scene wherever it is used
 * ({@link #named}): the workbench's generators, its benchmark, the contract and the course draw
 * it, and the bundled {@code uniform-200}, {@code clustered-200} and {@code overlapping-60} are
 * such scenes written to files. The workbench's scenes live in [0, 10]^2, {@link #mixed} (every
 * kind of shape) in [0, 100]^2; {@link #aligned} puts shapes in shared planes on purpose.
 */
public final class Shapes {
    /** The seed of the scene of a name and a count ({@link #named}). */
    public static final long SEED = 1;

    private Shapes() {
    }

    /**
     * The scene of a name and a count, drawn with seed {@link #SEED}.
     *
     * @param name {@code uniform}, {@code clustered}, {@code overlapping} or {@code mixed}
     * @param n the number of shapes
     * @return the scene
     * @throws IllegalArgumentException for another name
     */
    public static Scene2D named(String name, int n) {
        return switch (name) {
            case "uniform" -> uniform(n, SEED);
            case "clustered" -> clustered(n, SEED);
            case "overlapping" -> overlapping(n, SEED);
            case "mixed" -> mixed(n, SEED);
            default -> throw new IllegalArgumentException("no generated 2-D scene '" + name + "' (uniform, clustered, overlapping, mixed)");
        };
    }

    /**
     * {@return {@code n} small triangles spread uniformly over [0, 10]^2}
     *
     * @param n the number of triangles
     * @param seed the random seed
     */
    public static Scene2D uniform(int n, long seed) {
        Random r = new Random(seed);
        List<Shape2D> out = new ArrayList<>(n);
        double s = Math.max(0.02, 3.0 / Math.sqrt(Math.max(n, 1)));
        for (int i = 0; i < n; i++) out.add(smallTriangle(r, r.nextDouble() * 10, r.nextDouble() * 10, s));
        return new Scene2D(out);
    }


    /**
     * {@return {@code n} small triangles in five tight clusters ({@code Clusters}, standard deviation
     * 0.5, centres in [1, 9]^2), taken in turn, with empty space between}: where the SAH shines.
     *
     * @param n the number of triangles
     * @param seed the random seed
     */
    public static Scene2D clustered(int n, long seed) {
        Random r = new Random(seed);
        Clusters clusters = Clusters.draw(r, 5, 2, 1, 9);
        List<Shape2D> out = new ArrayList<>(n);
        double s = Math.max(0.01, 1.0 / Math.sqrt(Math.max(n, 1)));
        double[] p = new double[2];
        for (int i = 0; i < n; i++) {
            clusters.member(r, i % clusters.count(), 0.5, p, 0);
            out.add(smallTriangle(r, clamp(p[0]), clamp(p[1]), s));
        }
        return new Scene2D(out);
    }


    /**
     * {@return {@code n} large rectangles piled on one another}: no plane separates them.
     *
     * @param n the number of rectangles
     * @param seed the random seed
     */
    public static Scene2D overlapping(int n, long seed) {
        Random r = new Random(seed);
        List<Shape2D> out = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            double x = 3 + 2 * r.nextDouble(), y = 3 + 2 * r.nextDouble();
            out.add(new Shape2D.Rect(x - 2, y - 2, x + 1 + 2 * r.nextDouble(), y + 1 + 2 * r.nextDouble()));
        }
        return new Scene2D(out);
    }


    /** {@return a long thin diagonal segment across a field of 40 small rectangles}: it lands in many leaves. */
    public static Scene2D longThin() {
        Random r = new Random(7);
        List<Shape2D> out = new ArrayList<>();
        for (int i = 0; i < 40; i++) {
            double x = r.nextDouble() * 9.5, y = r.nextDouble() * 9.5;
            out.add(new Shape2D.Rect(x, y, x + 0.2 + 0.3 * r.nextDouble(), y + 0.2 + 0.3 * r.nextDouble()));
        }
        out.add(new Shape2D.Segment(0.2, 0.5, 9.8, 9.6));
        return new Scene2D(out);
    }

    /**
     * {@return {@code n} shapes of every kind in turn (point, segment, rectangle, triangle) at
     * uniform places in [0, 100]^2, of sizes up to about 8}: the contract's and the course's "mixed
     * 2-D shapes" (400 of them), the workbench's "Mixed shapes", the scenes of the contract's
     * property "any random 2-D scene".
     *
     * @param n the number of shapes
     * @param seed the random seed
     */
    public static Scene2D mixed(int n, long seed) {
        Random r = new Random(seed);
        List<Shape2D> shapes = new ArrayList<>(n);
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
     * {@return {@code n} shapes of every kind, aligned on purpose}: x on a grid of quarters in
     * [0, 10), vertical segments (planar in x), points at whole y; triangles, slanted segments and
     * rectangles between. Many shapes lie in the planes a builder considers.
     *
     * @param n the number of shapes
     * @param seed the random seed
     */
    public static Scene2D aligned(int n, long seed) {
        Random r = new Random(seed);
        List<Shape2D> s = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            double x = r.nextInt(40) / 4.0, y = r.nextDouble() * 10;
            switch (i % 5) {
                case 0 -> s.add(new Shape2D.Triangle(x, y, x + r.nextDouble(), y + r.nextDouble(), x - r.nextDouble(), y + 2 * r.nextDouble()));
                case 1 -> s.add(new Shape2D.Segment(x, y, x, y + r.nextDouble()));
                case 2 -> s.add(new Shape2D.Segment(x, y, x + 2 * r.nextDouble(), y + r.nextDouble()));
                case 3 -> s.add(new Shape2D.Rect(x, y, x + r.nextDouble(), y + r.nextDouble()));
                default -> s.add(new Shape2D.Point(x, Math.floor(y)));
            }
        }
        return new Scene2D(s);
    }

    private static Shape2D smallTriangle(Random r, double x, double y, double s) {
        return new Shape2D.Triangle(x, y, clamp(x + s * (0.3 + r.nextDouble())), clamp(y + s * 0.5 * r.nextDouble()),
                clamp(x + s * 0.5 * r.nextDouble()), clamp(y + s * (0.3 + r.nextDouble())));
    }

    private static double clamp(double v) {
        return Math.max(0, Math.min(10, v));
    }
}
