package org.kdtree.kdtree;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import org.junit.jupiter.api.Test;
import org.kdtree.accel.BruteForce;
import org.kdtree.accel.Hit;
import org.kdtree.accel.Intersector;
import org.kdtree.accel.TriangleIntersector;
import org.kdtree.generate.Meshes;
import org.kdtree.geom.Ray;
import org.kdtree.shape.TriangleMesh;

class TriangleIntersectorTest {
    private static final double[] A = {0, 0, 0}, B = {1, 0, 0}, C = {0, 1, 0};

    private static TriangleIntersector one(double[] a, double[] b, double[] c) {
        return new TriangleIntersector(new MeshBuilder().triangle(a, b, c).build());
    }

    private static Hit shoot(Intersector x, double ox, double oy, double oz, double dx, double dy, double dz) {
        Hit h = new Hit();
        x.intersect(0, new Ray(3).set(ox, oy, oz, dx, dy, dz), 0, Double.POSITIVE_INFINITY, h);
        return h;
    }

    @Test void hitsInteriorWithBarycentrics() {
        Hit h = shoot(one(A, B, C), 0.25, 0.5, 2, 0, 0, -1);
        assertThat(h.primitive).isZero();
        assertThat(h.t).isEqualTo(2.0);
        assertThat(h.u).isCloseTo(0.25, within(1e-15));
        assertThat(h.v).isCloseTo(0.5, within(1e-15));
    }

    @Test void verticesAndEdgesAreHitFromBothSidesAndWithSignedZeroDirections() {
        TriangleIntersector x = one(A, B, C);
        double[][] points = {A, B, C, {0.5, 0, 0}, {0, 0.5, 0}, {0.5, 0.5, 0}};
        for (double[] p : points) {
            for (double dz : new double[] {-1, 1}) {
                for (double zero : new double[] {0.0, -0.0}) {
                    Hit h = shoot(x, p[0], p[1], p[2] - 3 * dz, zero, zero, dz);
                    assertThat(h.found()).as("point %s dz %s zero %s", java.util.Arrays.toString(p), dz, zero).isTrue();
                    assertThat(h.t).isEqualTo(3.0);
                }
            }
        }
    }

    @Test void justOutsideAnEdgeMisses() {
        // (Far smaller offsets, near 1e-308, underflow in the edge functions and count as on the edge.)
        Hit h = shoot(one(A, B, C), 0.5, -1e-300, 1, 0, 0, -1);
        assertThat(h.found()).isFalse();
    }

    @Test void zeroAreaTrianglesAreNeverHit() {
        double[][][] degenerate = {
                {A, A, B},                           // repeated vertex
                {A, A, A},                           // a point
                {{0, 0, 0}, {1, 1, 1}, {3, 3, 3}},   // collinear
                {{0.1, 0.2, 0.3}, {0.1 * 2, 0.2 * 2, 0.3 * 2}, {0.1 * 4, 0.2 * 4, 0.3 * 4}}, // exactly collinear
        };
        for (double[][] t : degenerate) {
            TriangleIntersector x = one(t[0], t[1], t[2]);
            assertThat(x.isDegenerate(0)).isTrue();
            for (double[] p : t) {
                assertThat(shoot(x, p[0] - 1, p[1], p[2], 1, 0, 0).found()).isFalse();
                assertThat(shoot(x, p[0], p[1] - 1, p[2], 0, 1, 0).found()).isFalse();
                assertThat(shoot(x, p[0], p[1], p[2] - 1, 0, 0, 1).found()).isFalse();
            }
        }
        assertThat(one(A, B, C).isDegenerate(0)).isFalse();
        // a triangle of 1e-300 is tiny, not degenerate; it must sit in a mesh of a supported extent (Tolerance.MIN_EXTENT)
        TriangleMesh tinyAndUnit = new TriangleMesh(new double[] {0, 0, 0, 1e-300, 0, 0, 0, 1e-300, 0, 1, 1, 1, 2, 1, 1, 1, 2, 1},
                new int[] {0, 1, 2, 3, 4, 5});
        assertThat(new TriangleIntersector(tinyAndUnit).isDegenerate(0)).isFalse();
    }

    @Test void edgeOnRaysMiss() {
        Hit h = shoot(one(A, B, C), -1, 0.25, 0, 1, 0, 0);
        assertThat(h.found()).isFalse();
    }

    @Test void respectsTheClosedRangeAndTheCurrentHit() {
        TriangleIntersector x = one(A, B, C);
        Ray r = new Ray(3).set(0.2, 0.2, 1, 0, 0, -1);
        Hit h = new Hit();
        assertThat(x.intersect(0, r, 0, 0.999, h)).isFalse();
        assertThat(x.intersect(0, r, 1, 1, h)).isTrue();
        assertThat(x.intersect(0, r, 0, 2, h)).as("not closer than the hit already held").isFalse();
        h.reset();
        assertThat(x.intersect(0, r, 1.0001, 2, h)).isFalse();
    }

    @Test void noRaySlipsThroughASharedEdgeOrVertexOfAClosedMesh() {
        TriangleMesh sphere = Scenes.sphere(0.3, -0.2, 0.1, 1.7, 12, 24);
        BruteForce brute = new BruteForce(new TriangleIntersector(sphere));
        Hit h = new Hit();
        Ray r = new Ray(3);
        java.util.Random rnd = new java.util.Random(5);
        int rays = 0;
        for (int t = 0; t < sphere.size(); t++) {
            for (int k = 0; k < 3; k++) {
                double[] p = new double[3], q = new double[3];
                for (int a = 0; a < 3; a++) {
                    p[a] = sphere.corner(t, k, a);
                    q[a] = (p[a] + sphere.corner(t, (k + 1) % 3, a)) / 2;
                }
                for (double[] target : new double[][] {p, q}) {
                    double ox = 0.3 + 0.5 * rnd.nextGaussian() * 0.3, oy = -0.2 + 0.3 * rnd.nextGaussian(),
                            oz = 0.1 + 0.3 * rnd.nextGaussian();
                    r.set(ox, oy, oz, target[0] - ox, target[1] - oy, target[2] - oz);
                    assertThat(brute.closestHit(r, 0, Double.POSITIVE_INFINITY, h)).as("ray %s", r).isTrue();
                    rays++;
                }
            }
        }
        assertThat(rays).isEqualTo(6 * sphere.size());
    }

    @Test void closestHitAllIsBruteForce() {
        TriangleMesh soup = Meshes.uniform(300, 0.3, 9);
        TriangleIntersector x = new TriangleIntersector(soup);
        BruteForce brute = new BruteForce(x);
        java.util.Random rnd = new java.util.Random(9);
        Ray r = new Ray(3);
        Hit a = new Hit(), b = new Hit();
        int hits = 0;
        for (int i = 0; i < 500; i++) {
            r.set(rnd.nextDouble(), rnd.nextDouble(), rnd.nextDouble(), rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian());
            boolean want = brute.closestHit(r, 0, Double.POSITIVE_INFINITY, a);
            assertThat(x.closestHitAll(r, 0, Double.POSITIVE_INFINITY, b)).isEqualTo(want);
            if (want) {
                hits++;
                assertThat(b.t).isEqualTo(a.t);
                assertThat(b.primitive).isEqualTo(a.primitive);
            }
        }
        assertThat(hits).isGreaterThan(100);
    }
}
