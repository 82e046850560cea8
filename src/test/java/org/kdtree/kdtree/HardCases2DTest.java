package org.kdtree.kdtree;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.kdtree.accel.Intersector;
import org.kdtree.geom.Ray;
import org.kdtree.shape.Scene2D;
import org.kdtree.shape.Shape2D;

/**
 * The hard cases in 2-D (segments, filled rectangles and triangles, points), for every builder and
 * its tree saved and loaded again (issue 43), against brute force.
 */
class HardCases2DTest {
    private static List<Oracle> oracles(Scene2D scene) {
        return Oracle.allBuildersAndSavedTrees(scene, Intersector.of(scene));
    }

    private static List<double[]> directions() {
        List<double[]> d = new ArrayList<>();
        for (double s : new double[] {1, -1})
            for (double z : new double[] {0.0, -0.0}) {
                d.add(new double[] {s, z});
                d.add(new double[] {z, s});
            }
        for (double sx : new double[] {1, -1})
            for (double sy : new double[] {1, -1}) {
                d.add(new double[] {sx, sy});
                d.add(new double[] {sx, 0.5 * sy});
            }
        return d;
    }

    private static int shootLattice(Scene2D scene, double scale) {
        int hits = 0;
        Ray ray = new Ray(2);
        for (Oracle o : oracles(scene)) {
            for (double x = -1; x <= 7; x += 0.5) {
                for (double y = -1; y <= 7; y += 0.5) {
                    for (double[] d : directions()) {
                        ray.set(x * scale, y * scale, d[0], d[1]);
                        if (o.check(ray)) hits++;
                        o.check(ray, 0.5 * scale, 1.5 * scale);
                    }
                }
            }
        }
        return hits;
    }

    @Test void latticeRaysInSplitLinesThroughVerticesWithSignedZeros() {
        assertThat(shootLattice(Scenes.grid2D(6), 1)).isGreaterThan(1000);
    }

    @Test void scaledScenes() {
        for (double s : new double[] {1e-6, 1e6}) {
            List<Shape2D> scaled = new ArrayList<>();
            for (Shape2D sh : Scenes.grid2D(6).shapes()) scaled.add(scale(sh, s));
            assertThat(shootLattice(new Scene2D(scaled), s)).isGreaterThan(1000);
        }
    }

    @Test void originsFarAwayAndDegenerateShapes() {
        List<Shape2D> shapes = new ArrayList<>(Scenes.grid2D(4).shapes());
        shapes.add(new Shape2D.Rect(1, 1, 1, 3));                  // zero width
        shapes.add(new Shape2D.Triangle(0, 0, 1, 1, 2, 2));        // collinear
        shapes.add(new Shape2D.Segment(2, 2, 2, 2));               // a point-like segment
        Scene2D scene = new Scene2D(shapes);
        Ray ray = new Ray(2);
        int hits = 0;
        for (Oracle o : oracles(scene)) {
            for (double[] d : directions()) {
                for (double x = 0; x <= 4; x += 0.5) {
                    for (double y = 0; y <= 4; y += 1) {
                        ray.set(x - 1e7 * d[0], y - 1e7 * d[1], d[0], d[1]);
                        if (o.check(ray)) hits++;
                    }
                }
            }
        }
        assertThat(hits).isGreaterThan(100);
    }

    private static Shape2D scale(Shape2D s, double f) {
        double[] c = s.coords();
        for (int i = 0; i < c.length; i++) c[i] *= f;
        if (s instanceof Shape2D.Point) return new Shape2D.Point(c[0], c[1]);
        if (s instanceof Shape2D.Segment) return new Shape2D.Segment(c[0], c[1], c[2], c[3]);
        if (s instanceof Shape2D.Rect) return new Shape2D.Rect(c[0], c[1], c[2], c[3]);
        return new Shape2D.Triangle(c[0], c[1], c[2], c[3], c[4], c[5]);
    }
}
