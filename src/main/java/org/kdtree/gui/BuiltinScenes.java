package org.kdtree.gui;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.function.Supplier;
import org.kdtree.io.BundledScenes;
import org.kdtree.io.Scene2DReader;
import org.kdtree.shape.Shape2D;

/**
 * The 2-D scenes the workbench offers without a file, and random generators with a count.
 * The named scenes are the bundled {@code .scene2d} files ({@link BundledScenes}), so that a
 * name means the same shapes, and the same cost, in the workbench, the command line and the
 * contract; the generators made them. Every scene lives in the square [0, 10] x [0, 10];
 * random scenes are seeded, so the same count gives the same scene.
 */
public final class BuiltinScenes {
    private BuiltinScenes() {
    }

    /** {@return the built-in scenes by name, in menu order}; the first is the one the workbench opens on. */
    public static Map<String, Supplier<List<Shape2D>>> all() {
        Map<String, Supplier<List<Shape2D>>> m = new LinkedHashMap<>();
        m.put("Talk figures", BuiltinScenes::talkFigures);
        m.put("Uniform (200)", () -> bundled("uniform-200.scene2d"));
        m.put("Clustered (200)", () -> bundled("clustered-200.scene2d"));
        m.put("Long thin object", () -> bundled("long-thin.scene2d"));
        m.put("Many overlapping (60)", () -> bundled("overlapping-60.scene2d"));
        return m;
    }

    private static List<Shape2D> bundled(String file) {
        try {
            return Scene2DReader.read(BundledScenes.path(file)).shapes();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** {@return the random generators by name, each taking a count} */
    public static Map<String, java.util.function.IntFunction<List<Shape2D>>> generators() {
        Map<String, java.util.function.IntFunction<List<Shape2D>>> m = new LinkedHashMap<>();
        m.put("Uniform", n -> uniform(n, n));
        m.put("Clustered", n -> clustered(n, n));
        m.put("Overlapping", n -> overlapping(n, n));
        m.put("Mixed shapes", n -> mixed(n, n));
        return m;
    }

    /**
     * {@return the talk's figures 2-5, the bundled scenes/talk-figures.scene2d}: two small objects at the left, a long thin one, a cluster at the right.
     */
    public static List<Shape2D> talkFigures() {
        return bundled("talk-figures.scene2d");
    }

    /**
     * {@return {@code n} small triangles spread uniformly}
     *
     * @param n the number of triangles
     * @param seed the random seed
     */
    public static List<Shape2D> uniform(int n, long seed) {
        Random r = new Random(seed);
        List<Shape2D> out = new ArrayList<>(n);
        double s = Math.max(0.02, 3.0 / Math.sqrt(Math.max(n, 1)));
        for (int i = 0; i < n; i++) out.add(smallTriangle(r, r.nextDouble() * 10, r.nextDouble() * 10, s));
        return out;
    }

    /**
     * {@return {@code n} small triangles in a few tight clusters, with empty space between}: where the SAH shines.
     *
     * @param n the number of triangles
     * @param seed the random seed
     */
    public static List<Shape2D> clustered(int n, long seed) {
        Random r = new Random(seed);
        int k = 5;
        double[][] centres = new double[k][];
        for (int c = 0; c < k; c++) centres[c] = new double[] {1 + 8 * r.nextDouble(), 1 + 8 * r.nextDouble()};
        List<Shape2D> out = new ArrayList<>(n);
        double s = Math.max(0.01, 1.0 / Math.sqrt(Math.max(n, 1)));
        for (int i = 0; i < n; i++) {
            double[] c = centres[i % k];
            double x = clamp(c[0] + 0.5 * r.nextGaussian()), y = clamp(c[1] + 0.5 * r.nextGaussian());
            out.add(smallTriangle(r, x, y, s));
        }
        return out;
    }

    /** {@return a long thin diagonal segment across a field of small rectangles}: it lands in many leaves. */
    public static List<Shape2D> longThin() {
        List<Shape2D> out = new ArrayList<>(uniformRects(40, 7));
        out.add(new Shape2D.Segment(0.2, 0.5, 9.8, 9.6));
        return out;
    }

    /**
     * {@return {@code n} large rectangles piled on one another}: no plane separates them.
     *
     * @param n the number of rectangles
     * @param seed the random seed
     */
    public static List<Shape2D> overlapping(int n, long seed) {
        Random r = new Random(seed);
        List<Shape2D> out = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            double x = 3 + 2 * r.nextDouble(), y = 3 + 2 * r.nextDouble();
            out.add(new Shape2D.Rect(x - 2, y - 2, x + 1 + 2 * r.nextDouble(), y + 1 + 2 * r.nextDouble()));
        }
        return out;
    }

    /**
     * {@return points, segments, rectangles and triangles, in turn}
     *
     * @param n the number of objects
     * @param seed the random seed
     */
    public static List<Shape2D> mixed(int n, long seed) {
        Random r = new Random(seed);
        List<Shape2D> out = new ArrayList<>(n);
        double s = Math.max(0.02, 3.0 / Math.sqrt(Math.max(n, 1)));
        for (int i = 0; i < n; i++) {
            double x = r.nextDouble() * 10, y = r.nextDouble() * 10;
            out.add(switch (i % 4) {
                case 0 -> new Shape2D.Point(x, y);
                case 1 -> new Shape2D.Segment(x, y, clamp(x + s * r.nextGaussian()), clamp(y + s * r.nextGaussian()));
                case 2 -> new Shape2D.Rect(x, y, clamp(x + s * r.nextDouble()), clamp(y + s * r.nextDouble()));
                default -> smallTriangle(r, x, y, s);
            });
        }
        return out;
    }

    private static List<Shape2D> uniformRects(int n, long seed) {
        Random r = new Random(seed);
        List<Shape2D> out = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            double x = r.nextDouble() * 9.5, y = r.nextDouble() * 9.5;
            out.add(new Shape2D.Rect(x, y, x + 0.2 + 0.3 * r.nextDouble(), y + 0.2 + 0.3 * r.nextDouble()));
        }
        return out;
    }

    private static Shape2D smallTriangle(Random r, double x, double y, double s) {
        return new Shape2D.Triangle(x, y, clamp(x + s * (0.3 + r.nextDouble())), clamp(y + s * 0.5 * r.nextDouble()),
                clamp(x + s * 0.5 * r.nextDouble()), clamp(y + s * (0.3 + r.nextDouble())));
    }

    private static double clamp(double v) {
        return Math.max(0, Math.min(10, v));
    }
}
