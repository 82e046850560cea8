package org.kdtree.collide;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.kdtree.shape.Scene2D;
import org.kdtree.shape.Shape2D;
import org.kdtree.testing.TestScenes;

/**
 * The exact primitive tests against a simple independent computation on random cases. Distance:
 * the minimum over a dense grid of points of the primitive is an upper bound U on the true
 * distance, and within the grid's spacing h of it; so U - h <= exact <= U. First contact: checked
 * with the (thus verified) distance along the path: it is r at the reported t, and above r at
 * every sampled earlier t (no contact at all: above r at every sample).
 */
class ExactTestsAgainstSamplingTest {
    private static final int GRID = 60, STEPS = 300;
    private static final double EPS = 1e-9;

    @Test void triangleDistanceAndSweepAgreeWithSampling() {
        Random rnd = new Random(16);
        MeshCollider c = new MeshCollider(MESH);
        double[] p = new double[3], out = new double[3];
        for (int tri = 0; tri < c.size(); tri++) {
            double h = longestEdge(tri) / GRID;
            for (int i = 0; i < 5; i++) {
                for (int a = 0; a < 3; a++) p[a] = rnd.nextDouble() * 1.6 - 0.3;
                double exact = Math.sqrt(c.closestPoint(tri, p, out));
                double sampled = sampledTriangleDistance(tri, p);
                assertThat(exact).as("triangle " + tri).isBetween(sampled - h - EPS, sampled + EPS);
                assertThat(Math.sqrt(SweptPoint.distanceSquared(out[0], out[1], out[2], p[0], p[1], p[2])))
                        .isCloseTo(exact, org.assertj.core.api.Assertions.within(EPS));
            }
            for (int i = 0; i < 3; i++) {
                double[] s = {rnd.nextDouble() * 1.6 - 0.3, rnd.nextDouble() * 1.6 - 0.3, rnd.nextDouble() * 1.6 - 0.3};
                double[] d = {rnd.nextGaussian() * 0.5, rnd.nextGaussian() * 0.5, rnd.nextGaussian() * 0.5};
                checkSweep(c, tri, s, d, rnd.nextDouble() * 0.2);
            }
        }
    }

    @Test void shapeDistanceAndSweepAgreeWithSampling() {
        Random rnd = new Random(17);
        Scene2D scene = TestScenes.random2D(200, 5);
        ShapeCollider c = new ShapeCollider(scene);
        double[] out = new double[3];
        for (int i = 0; i < scene.size(); i++) {
            List<double[]> samples = samples(scene.get(i));
            double h = spacing(scene.get(i));
            for (int j = 0; j < 5; j++) {
                double[] p = {rnd.nextDouble() * 110 - 5, rnd.nextDouble() * 110 - 5};
                double exact = Math.sqrt(c.closestPoint(i, p, out));
                if (Double.isInfinite(exact)) continue; // a zero-area shape: never touched
                double sampled = Double.POSITIVE_INFINITY;
                for (double[] q : samples) sampled = Math.min(sampled, Math.hypot(q[0] - p[0], q[1] - p[1]));
                assertThat(exact).as(scene.describe(i)).isBetween(sampled - h - EPS, sampled + EPS);
            }
            for (int j = 0; j < 3; j++) {
                double[] s = {rnd.nextDouble() * 110 - 5, rnd.nextDouble() * 110 - 5};
                double[] d = {rnd.nextGaussian() * 15, rnd.nextGaussian() * 15};
                checkSweep(c, i, s, d, rnd.nextDouble() * 5);
            }
        }
    }

    private static void checkSweep(Collider c, int prim, double[] s, double[] d, double r) {
        double t = c.firstContact(prim, s, d, r, 1);
        String ctx = "primitive " + prim + " s=" + java.util.Arrays.toString(s) + " d=" + java.util.Arrays.toString(d) + " r=" + r + " t=" + t;
        if (t < Double.POSITIVE_INFINITY) {
            double at = distanceAt(c, prim, s, d, t);
            if (t == 0) assertThat(at).as(ctx).isLessThanOrEqualTo(r + EPS);
            else assertThat(at).as(ctx).isCloseTo(r, org.assertj.core.api.Assertions.within(EPS));
        }
        for (int k = 0; k <= STEPS; k++) {
            double u = (double) k / STEPS;
            if (u >= t - EPS) break;
            assertThat(distanceAt(c, prim, s, d, u)).as(ctx + " at " + u).isGreaterThan(r - EPS);
        }
    }

    private static double distanceAt(Collider c, int prim, double[] s, double[] d, double t) {
        double[] p = new double[s.length];
        for (int a = 0; a < p.length; a++) p[a] = s[a] + t * d[a];
        return Math.sqrt(c.closestPoint(prim, p, null));
    }

    private static double sampledTriangleDistance(int tri, double[] p) {
        double[] a = cornerOf(tri, 0), b = cornerOf(tri, 1), q = cornerOf(tri, 2);
        double best = Double.POSITIVE_INFINITY;
        for (int i = 0; i <= GRID; i++) {
            for (int j = 0; i + j <= GRID; j++) {
                double u = (double) i / GRID, v = (double) j / GRID, dist = 0;
                for (int k = 0; k < 3; k++) {
                    double x = a[k] + u * (b[k] - a[k]) + v * (q[k] - a[k]) - p[k];
                    dist += x * x;
                }
                best = Math.min(best, Math.sqrt(dist));
            }
        }
        return best;
    }

    private static final org.kdtree.shape.TriangleMesh MESH = TestScenes.randomTriangles(100, 0.3, 3);

    private static double[] cornerOf(int tri, int k) {
        return new double[] {MESH.corner(tri, k, 0), MESH.corner(tri, k, 1), MESH.corner(tri, k, 2)};
    }

    private static double longestEdge(int tri) {
        double m = 0;
        for (int k = 0; k < 3; k++) {
            double[] a = cornerOf(tri, k), b = cornerOf(tri, (k + 1) % 3);
            m = Math.max(m, Math.sqrt(SweptPoint.distanceSquared(a[0], a[1], a[2], b[0], b[1], b[2])));
        }
        return m;
    }

    /** Dense points of a 2-D shape (filled shapes: their area). */
    private static List<double[]> samples(Shape2D s) {
        double[] c = s.coords();
        List<double[]> out = new java.util.ArrayList<>();
        if (s instanceof Shape2D.Point) out.add(c);
        else if (s instanceof Shape2D.Segment) {
            for (int i = 0; i <= GRID * 4; i++) {
                double u = (double) i / (GRID * 4);
                out.add(new double[] {c[0] + u * (c[2] - c[0]), c[1] + u * (c[3] - c[1])});
            }
        } else if (s instanceof Shape2D.Rect) {
            for (int i = 0; i <= GRID; i++)
                for (int j = 0; j <= GRID; j++)
                    out.add(new double[] {c[0] + (c[2] - c[0]) * i / GRID, c[1] + (c[3] - c[1]) * j / GRID});
        } else {
            for (int i = 0; i <= GRID; i++)
                for (int j = 0; i + j <= GRID; j++) {
                    double u = (double) i / GRID, v = (double) j / GRID;
                    out.add(new double[] {c[0] + u * (c[2] - c[0]) + v * (c[4] - c[0]), c[1] + u * (c[3] - c[1]) + v * (c[5] - c[1])});
                }
        }
        return out;
    }

    /** The largest distance from a point of the shape to the nearest sample. */
    private static double spacing(Shape2D s) {
        double[] c = s.coords();
        double m = 0;
        for (int i = 0; i + 1 < c.length; i += 2)
            for (int j = 0; j + 1 < c.length; j += 2) m = Math.max(m, Math.hypot(c[i] - c[j], c[i + 1] - c[j + 1]));
        return s instanceof Shape2D.Segment ? m / (GRID * 4) : 2 * m / GRID;
    }
}
