package org.kdtree.kdtree;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.kdtree.accel.Hit;
import org.kdtree.accel.TriangleIntersector;
import org.kdtree.generate.HardMeshes;
import org.kdtree.geom.Ray;
import org.kdtree.shape.TriangleMesh;

/**
 * Havran's hard cases in 3-D, for every builder and for each builder's tree saved and loaded
 * again (issue 43), each ray checked against brute force by {@link Oracle} (closest t within
 * 1e-9 relative, same or equally close primitive, any hit).
 * The scenes are axis-aligned: every face, edge and vertex lies in a candidate split plane.
 */
class HardCases3DTest {
    private static final double[] ZEROS = {0.0, -0.0};

    /** A 4 x 4 x 4 grid cube with unit boxes inside, some touching, one planar quad, degenerate triangles. */
    static TriangleMesh boxes() {
        MeshBuilder b = new MeshBuilder().mesh(Scenes.gridCube(4, 1));
        b.box(1, 1, 1, 2, 2, 2).box(2, 2, 1, 3, 3, 2).box(1, 2, 2, 2, 3, 3); // share edges and vertices
        b.quad(new double[] {2, 0, 2}, new double[] {3, 0, 2}, new double[] {3, 4, 2}, new double[] {2, 4, 2}); // planar in z = 2
        b.triangle(new double[] {1, 3, 1}, new double[] {2, 3, 1}, new double[] {3, 3, 1});   // collinear
        b.triangle(new double[] {3, 1, 3}, new double[] {3, 1, 3}, new double[] {3, 2, 3});   // repeated vertex
        b.triangle(new double[] {1, 1, 3}, new double[] {1, 1, 3}, new double[] {1, 1, 3});   // a point
        return b.build();
    }

    /** Axis-parallel directions with signed zeros, diagonals within axis planes, and space diagonals. */
    static List<double[]> directions() {
        List<double[]> d = new ArrayList<>();
        for (int axis = 0; axis < 3; axis++)
            for (double s : new double[] {1, -1})
                for (double z1 : ZEROS)
                    for (double z2 : ZEROS) {
                        double[] v = new double[3];
                        v[axis] = s;
                        v[(axis + 1) % 3] = z1;
                        v[(axis + 2) % 3] = z2;
                        d.add(v);
                    }
        for (int axis = 0; axis < 3; axis++)
            for (double s1 : new double[] {1, -1})
                for (double s2 : new double[] {1, -1})
                    for (double z : ZEROS) {
                        double[] v = new double[3];
                        v[axis] = z;
                        v[(axis + 1) % 3] = s1;
                        v[(axis + 2) % 3] = s2 * 0.5;
                        d.add(v);
                    }
        for (int i = 0; i < 8; i++) d.add(new double[] {(i & 1) == 0 ? 1 : -1, (i & 2) == 0 ? 0.75 : -0.75, (i & 4) == 0 ? 0.5 : -1.25});
        return d;
    }

    private static int shoot(TriangleMesh mesh, double[][] origins, List<double[]> dirs, double scale) {
        int hits = 0;
        Ray ray = new Ray(3);
        for (Oracle o : Oracle.allBuildersAndSavedTrees(mesh, new TriangleIntersector(mesh))) {
            for (double[] p : origins) {
                for (double[] d : dirs) {
                    ray.set(p[0] * scale, p[1] * scale, p[2] * scale, d[0], d[1], d[2]);
                    if (o.check(ray)) hits++;
                    o.check(ray, 0.5 * scale, 2.5 * scale);     // caller's range, ties at voxel faces
                    o.check(ray, 1 * scale, 1 * scale);         // a single t, on a plane
                }
            }
        }
        return hits;
    }

    /** Lattice points (on split planes, voxel corners and edges), face centres, voxel centres. */
    private static double[][] origins() {
        List<double[]> o = new ArrayList<>();
        for (double x = -1; x <= 5; x += 1.5)
            for (double y = -1; y <= 5; y += 1)
                for (double z = 0; z <= 4; z += 0.5) o.add(new double[] {x, y, z});
        return o.toArray(new double[0][]);
    }

    @Test void raysInSplitPlanesAndThroughEdgesAndVerticesWithSignedZeros() {
        assertThat(shoot(boxes(), origins(), directions(), 1)).isGreaterThan(1000);
    }

    @Test void scaledByOneMillionth() {
        TriangleMesh m = HardMeshes.scaled(boxes(), 1e-6);
        assertThat(shoot(m, origins(), directions(), 1e-6)).isGreaterThan(1000);
    }

    @Test void scaledByOneMillion() {
        TriangleMesh m = HardMeshes.scaled(boxes(), 1e6);
        assertThat(shoot(m, origins(), directions(), 1e6)).isGreaterThan(1000);
    }

    /** The ends of the supported range (geom.Tolerance): coordinates up to 1e100, extents down to 1e-100. */
    @Test void scaledToTheEndsOfTheSupportedRange() {
        for (double scale : new double[] {2e99, 1e-100})
            assertThat(shoot(HardMeshes.scaled(boxes(), scale), origins(), directions(), scale)).as("scale %s", scale)
                    .isGreaterThan(1000);
    }

    /** Beyond the range the products of the ray/triangle test overflow or underflow: the mesh is refused, with the reason. */
    /**
     * Far from the origin, with coordinates no float holds, the answers stay exact and the tree as
     * good as at the origin: planes are stored as doubles (a float plane would be 1/16 apart at
     * 10^6 and 2^19 at 7.77e12, and triangles meeting at a vertex could not be separated).
     */
    @Test void movedFarFromTheOriginWithCoordinatesNoFloatHolds() {
        for (double[] offset : new double[][] {{1e6 + 0.1, -3e7 - 0.3, 12345.678}, {-7.77e12, 1e9 / 3, 0.1}}) {
            TriangleMesh m = MeshBuilder.moved(boxes(), offset);
            int hits = 0;
            Ray ray = new Ray(3);
            for (Oracle o : Oracle.allBuildersAndSavedTrees(m, new TriangleIntersector(m)))
                for (double[] p : origins())
                    for (double[] d : directions()) {
                        ray.set(p[0] + offset[0], p[1] + offset[1], p[2] + offset[2], d[0], d[1], d[2]);
                        if (o.check(ray)) hits++;
                    }
            assertThat(hits).as("offset %s", java.util.Arrays.toString(offset)).isGreaterThan(1000);
            double here = new org.kdtree.kdtree.SahBuilder().build(boxes()).stats().expectedCost();
            double there = new org.kdtree.kdtree.SahBuilder().build(m).stats().expectedCost();
            assertThat(there).as("expected cost moved vs at the origin").isCloseTo(here, org.assertj.core.data.Percentage.withPercentage(2));
        }
    }

    @Test void scalesBeyondTheRangeAreRefusedNotAnsweredWrongly() {
        for (double scale : new double[] {1e110, 1e150, 1e300})
            org.assertj.core.api.Assertions.assertThatThrownBy(() -> HardMeshes.scaled(boxes(), scale))
                    .isInstanceOf(org.kdtree.shape.InvalidGeometryException.class).hasMessageContaining("-1e100 .. 1e100");
        for (double scale : new double[] {1e-110, 1e-150, 1e-300})
            org.assertj.core.api.Assertions.assertThatThrownBy(() -> HardMeshes.scaled(boxes(), scale))
                    .isInstanceOf(org.kdtree.shape.InvalidGeometryException.class).hasMessageContaining("smallest supported extent is 1e-100");
    }

    @Test void originsFarAwayAimedAtVerticesAndEdges() {
        TriangleMesh m = boxes();
        List<Oracle> oracles = Oracle.allBuildersAndSavedTrees(m, new TriangleIntersector(m));
        Ray ray = new Ray(3);
        int hits = 0;
        for (double[] d : directions()) {
            for (double x = 0; x <= 4; x += 0.5) {
                for (double y = 0; y <= 4; y += 1) {
                    for (double z = 0; z <= 4; z += 2) {
                        ray.set(x - 1e7 * d[0], y - 1e7 * d[1], z - 1e7 * d[2], d[0], d[1], d[2]);
                        for (Oracle o : oracles) if (o.check(ray)) hits++;
                    }
                }
            }
        }
        assertThat(hits).isGreaterThan(1000);
    }

    @Test void flatSceneWithRaysInItsPlane() {
        MeshBuilder b = new MeshBuilder();
        for (int i = 0; i < 4; i++)
            for (int j = 0; j < 4; j++)
                b.quad(new double[] {i, j, 0}, new double[] {i + 1, j, 0}, new double[] {i + 1, j + 1, 0},
                        new double[] {i, j + 1, 0});
        TriangleMesh flat = b.build();
        List<double[]> o = new ArrayList<>();
        for (double x = -1; x <= 5; x += 0.5)
            for (double y = -1; y <= 5; y += 1) {
                o.add(new double[] {x, y, 0});
                o.add(new double[] {x, y, 1});
                o.add(new double[] {x, y, -2});
            }
        List<double[]> dirs = new ArrayList<>(directions());
        dirs.add(new double[] {0.25, 0.5, -1});
        int hits = shoot(flat, o.toArray(new double[0][]), dirs, 1);
        assertThat(hits).isGreaterThan(100);
    }

    @Test void grazingRaysAlongFacesAndEdges() {
        TriangleMesh m = boxes();
        List<Oracle> oracles = Oracle.allBuildersAndSavedTrees(m, new TriangleIntersector(m));
        Ray ray = new Ray(3);
        java.util.Random rnd = new java.util.Random(11);
        int hits = 0;
        for (int i = 0; i < 3000; i++) {
            // Lie in a face plane (z = integer), a tiny tilt or none.
            double z = rnd.nextInt(5), tilt = rnd.nextBoolean() ? 0.0 : (rnd.nextBoolean() ? 1e-12 : -0.0);
            ray.set(rnd.nextDouble() * 6 - 1, rnd.nextDouble() * 6 - 1, z, rnd.nextGaussian(), rnd.nextGaussian(), tilt);
            for (Oracle o : oracles) if (o.check(ray)) hits++;
        }
        assertThat(hits).isGreaterThan(1000);
    }

    @Test void degenerateTrianglesAreNeverReported() {
        TriangleMesh m = boxes();
        TriangleIntersector x = new TriangleIntersector(m);
        int n = m.size();
        assertThat(x.isDegenerate(n - 1)).isTrue();
        assertThat(x.isDegenerate(n - 2)).isTrue();
        assertThat(x.isDegenerate(n - 3)).isTrue();
        Traverser t = new Traverser(org.kdtree.spec.Builders.create("sah").build(m));
        Ray ray = new Ray(3);
        for (double[] d : directions()) {
            for (double[] p : new double[][] {{1, 3, 1}, {2, 3, 1}, {2.5, 3, 1}, {3, 1, 3}, {3, 1.5, 3}, {1, 1, 3}}) {
                ray.set(p[0] - d[0], p[1] - d[1], p[2] - d[2], d[0], d[1], d[2]);
                for (Hit h : t.allHits(ray, 0, Double.POSITIVE_INFINITY)) assertThat(h.primitive).isLessThan(n - 3);
            }
        }
    }
}
