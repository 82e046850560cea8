package org.kdtree.kdtree;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.kdtree.accel.Hit;
import org.kdtree.accel.TriangleIntersector;
import org.kdtree.geom.Ray;
import org.kdtree.shape.TriangleMesh;
import org.kdtree.spec.Builders;

/**
 * Closed meshes leak no ray: from inside, every ray hits (watertight triangle test plus a
 * traversal that never loses a voxel); rays aimed exactly at shared vertices and edges hit.
 */
class ClosedMeshTest {
    private static final int MILLION = 1_000_000;

    private static long leaks(TriangleMesh mesh, double[] lo, double[] hi, int rays, long seed) {
        Traverser t = new Traverser(Builders.create("sah").build(mesh));
        SplittableRandom rnd = new SplittableRandom(seed);
        Ray ray = new Ray(3);
        Hit hit = new Hit();
        long misses = 0;
        for (int i = 0; i < rays; i++) {
            ray.set(lo[0] + rnd.nextDouble() * (hi[0] - lo[0]), lo[1] + rnd.nextDouble() * (hi[1] - lo[1]),
                    lo[2] + rnd.nextDouble() * (hi[2] - lo[2]), rnd.nextDouble(-1, 1), rnd.nextDouble(-1, 1),
                    rnd.nextDouble(-1, 1));
            if (!t.closestHit(ray, 0, Double.POSITIVE_INFINITY, hit)) misses++;
        }
        return misses;
    }

    @Test void aMillionRaysFromInsideATessellatedSphereAllHit() {
        TriangleMesh sphere = Scenes.sphere(0.1, 0.2, -0.3, 1, 32, 64);
        double[] lo = {0.1 - 0.5, 0.2 - 0.5, -0.3 - 0.5}, hi = {0.1 + 0.5, 0.2 + 0.5, -0.3 + 0.5};
        assertThat(leaks(sphere, lo, hi, MILLION, 1)).isZero();
    }

    @Test void aMillionRaysFromInsideAGridCubeAllHit() {
        // Origins anywhere inside, including on the interior lattice planes x, y, z = 1, 2, 3 (by chance
        // rarely; the test below covers them on purpose).
        TriangleMesh cube = Scenes.gridCube(4, 1);
        assertThat(leaks(cube, new double[] {0, 0, 0}, new double[] {4, 4, 4}, MILLION, 2)).isZero();
    }

    @Test void raysFromLatticePointsInsideTheCubeTowardEveryVertexAndEdgeHit() {
        TriangleMesh cube = Scenes.gridCube(4, 1);
        for (Oracle o : Oracle.allBuilders(cube, new TriangleIntersector(cube))) {
            Ray ray = new Ray(3);
            int hits = 0, rays = 0;
            for (double[] from : new double[][] {{2, 2, 2}, {1, 1, 1}, {1, 2, 3}, {0.5, 3.5, 2}, {3, 0.5, 0.5}}) {
                for (int t = 0; t < cube.size(); t++) {
                    for (int k = 0; k < 3; k++) {
                        double[] p = new double[3];
                        for (int a = 0; a < 3; a++) p[a] = (cube.corner(t, k, a) + cube.corner(t, (k + 1) % 3, a)) / 2;
                        double[][] targets = {{cube.corner(t, k, 0), cube.corner(t, k, 1), cube.corner(t, k, 2)}, p};
                        for (double[] q : targets) {
                            ray.set(from[0], from[1], from[2], q[0] - from[0], q[1] - from[1], q[2] - from[2]);
                            rays++;
                            if (o.check(ray)) hits++;
                        }
                    }
                }
            }
            assertThat(hits).as(o.name).isEqualTo(rays);
        }
    }

    @Test void raysAimedAtSphereVerticesAndEdgesFromOutsideHit() {
        TriangleMesh sphere = Scenes.sphere(0, 0, 0, 1, 12, 24);
        List<Oracle> oracles = Oracle.allBuilders(sphere, new TriangleIntersector(sphere));
        Ray ray = new Ray(3);
        for (int t = 0; t < sphere.size(); t++) {
            for (int k = 0; k < 3; k++) {
                double[] q = new double[3];
                for (int a = 0; a < 3; a++) q[a] = sphere.corner(t, k, a);
                // From outside along the outward normal direction (roughly q itself): never a silhouette.
                ray.set(3 * q[0], 3 * q[1], 3 * q[2], -2 * q[0], -2 * q[1], -2 * q[2]);
                for (Oracle o : oracles) assertThat(o.check(ray)).as(o.name + " " + ray).isTrue();
            }
        }
    }
}
