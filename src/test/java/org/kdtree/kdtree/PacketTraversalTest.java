package org.kdtree.kdtree;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.kdtree.accel.BruteForce;
import org.kdtree.accel.Hit;
import org.kdtree.accel.PacketQuery;
import org.kdtree.accel.RayPacket;
import org.kdtree.accel.RayQuery;
import org.kdtree.accel.TriangleIntersector;
import org.kdtree.geom.Ray;
import org.kdtree.shape.TriangleMesh;
import org.kdtree.spec.Builders;

/**
 * The kd-tree's packet loop ({@link PacketTraversal}) gives every ray of a packet, closest hit and
 * any hit, the answer the ray gets alone through the single-ray loop (bit for bit) and the answer
 * of brute force over all triangles: coherent camera tiles, incoherent packets of mixed octants,
 * rays through shared edges and vertices and nearly in split planes, packets where only some rays
 * enter the scene or stay active, and empty packets; on every kd-tree builder's tree.
 */
class PacketTraversalTest {
    private static final String[] BUILDERS = {"sah", "median-plane", "object-median", "sliding-midpoint"};

    /** Traces {@code rays} (6 numbers each) in packets of up to 64, closest and any hit, against single rays and brute force; {@return the hits} */
    private static int agree(TriangleMesh mesh, double[] rays, double tMin, double tMax) {
        BruteForce brute = new BruteForce(new TriangleIntersector(mesh));
        int hits = 0;
        for (String b : BUILDERS) {
            KdTree tree = Builders.create(b).build(mesh);
            PacketQuery packets = tree.packetQuery();
            assertThat(packets).isInstanceOf(PacketTraversal.class);
            assertThat(packets.tracesTogether()).isTrue();
            RayQuery single = tree.query();
            RayPacket p = new RayPacket();
            Ray ray = new Ray(3);
            Hit alone = new Hit(), oracle = new Hit();
            for (int from = 0; from < rays.length / 6; from += RayPacket.CAPACITY) {
                p.clear();
                for (int i = from; i < Math.min(rays.length / 6, from + RayPacket.CAPACITY); i++)
                    p.add(rays[6 * i], rays[6 * i + 1], rays[6 * i + 2], rays[6 * i + 3], rays[6 * i + 4], rays[6 * i + 5], tMin, tMax);
                packets.closestHits(p);
                for (int i = 0; i < p.size(); i++) {
                    p.ray(i, ray);
                    String what = b + " ray " + ray + " [" + tMin + ", " + tMax + "]";
                    boolean found = single.closestHit(ray, tMin, tMax, alone);
                    assertThat(p.found(i)).as(what).isEqualTo(found);
                    assertThat(p.primitive[i]).as(what).isEqualTo(alone.primitive);
                    assertThat(Double.doubleToLongBits(p.t[i])).as(what).isEqualTo(Double.doubleToLongBits(alone.t));
                    assertThat(Double.doubleToLongBits(p.u[i])).as(what).isEqualTo(Double.doubleToLongBits(alone.u));
                    assertThat(Double.doubleToLongBits(p.v[i])).as(what).isEqualTo(Double.doubleToLongBits(alone.v));
                    boolean want = brute.closestHit(ray, tMin, tMax, oracle);
                    assertThat(p.found(i)).as(what + " brute force " + oracle).isEqualTo(want);
                    if (want) assertThat(Oracle.TOLERANCE.equal(p.t[i], oracle.t)).as(what + " t, brute force " + oracle).isTrue();
                    if (want) hits++;
                }
                packets.anyHits(p);
                for (int i = 0; i < p.size(); i++) {
                    p.ray(i, ray);
                    boolean want = brute.anyHit(ray, tMin, tMax);
                    assertThat(single.anyHit(ray, tMin, tMax)).isEqualTo(want);
                    assertThat(p.found(i)).as(b + " any hit, ray " + ray + " [" + tMin + ", " + tMax + "]").isEqualTo(want);
                }
            }
        }
        return hits;
    }

    /** An 8 x 8 tile of rays from {@code eye} toward a square of side {@code size} centred at {@code at}, in the z = at[2] plane. */
    private static double[] tile(double[] eye, double[] at, double size, int n) {
        double[] r = new double[6 * n * n];
        for (int j = 0, k = 0; j < n; j++)
            for (int i = 0; i < n; i++) {
                double x = at[0] + size * ((i + 0.5) / n - 0.5), y = at[1] + size * ((j + 0.5) / n - 0.5);
                r[k++] = eye[0]; r[k++] = eye[1]; r[k++] = eye[2];
                r[k++] = x - eye[0]; r[k++] = y - eye[1]; r[k++] = at[2] - eye[2];
            }
        return r;
    }

    @Test void coherentCameraTiles() {
        TriangleMesh mesh = new MeshBuilder().mesh(Scenes.sphere(2, 2, 2, 1.5, 16, 32)).mesh(HardCases3DTest.boxes()).build();
        int hits = 0;
        for (double[] eye : new double[][] {{2.1, 2.2, 9}, {-3, 5.5, -4}, {2.5, 2.5, 2.5}})
            for (double[] at : new double[][] {{2, 2, 0}, {0.5, 3.5, 1}, {3, 1, 4}})
                hits += agree(mesh, tile(eye, at, 2.5, 8), 0, Double.POSITIVE_INFINITY);
        assertThat(hits).as("most rays hit").isGreaterThan(4 * 9 * 40);
    }

    @Test void incoherentPacketsOfMixedOctantsAndZeroComponents() {
        TriangleMesh mesh = new MeshBuilder().mesh(Scenes.sphere(2, 2, 2, 1.5, 12, 24)).mesh(HardCases3DTest.boxes()).build();
        SplittableRandom rnd = new SplittableRandom(17);
        double[] rays = new double[6 * 64 * 12];
        for (int i = 0; i < rays.length; i += 6) {
            for (int a = 0; a < 3; a++) rays[i + a] = rnd.nextDouble(-1, 5);
            for (int a = 0; a < 3; a++) rays[i + 3 + a] = rnd.nextDouble(-1, 1);
            if (i % 42 == 0) rays[i + 3 + (i / 6) % 3] = (i & 1) == 0 ? 0.0 : -0.0;   // no octant: traced alone
        }
        assertThat(agree(mesh, rays, 0, Double.POSITIVE_INFINITY)).isGreaterThan(300);
        agree(mesh, rays, 0.5, 2.5);
    }

    @Test void raysThroughSharedVerticesAndEdgesAndNearlyInSplitPlanes() {
        TriangleMesh mesh = HardCases3DTest.boxes();
        List<double[]> rays = new ArrayList<>();
        // From points on split planes toward every lattice point and edge midpoint of the cube's faces: one packet per origin, one octant or several.
        for (double[] o : new double[][] {{-1, -1, -1}, {0.5, 2, 2}, {2, 2, -3}, {5, 5, 5}, {1, 1, 1}})
            for (double x = 0; x <= 4; x += 0.5)
                for (double y = 0; y <= 4; y += 0.5) {
                    double[] to = {x, y, 4 - x / 2};
                    rays.add(new double[] {o[0], o[1], o[2], to[0] - o[0], to[1] - o[1], to[2] - o[2]});
                }
        // Nearly axis-parallel: a component of 1e-300 (its inverse finite, so the ray has an octant), along the lattice's planes.
        for (double a = 0; a <= 4; a += 1)
            for (double b = 0; b <= 4; b += 0.5) {
                rays.add(new double[] {-1, a, b, 1, 1e-300, 1e-300});
                rays.add(new double[] {a, 5, b, -1e-300, -1, 1e-300});
                rays.add(new double[] {a, b, -1, 1e-300, -1e-300, 1});
            }
        double[] flat = new double[6 * rays.size()];
        for (int i = 0; i < rays.size(); i++) System.arraycopy(rays.get(i), 0, flat, 6 * i, 6);
        assertThat(agree(mesh, flat, 0, Double.POSITIVE_INFINITY)).isGreaterThan(500);
        agree(mesh, flat, 1, 1);              // a single t, on a plane
        agree(mesh, flat, 0.5, 2.5);          // the caller's range, ties at voxel faces
    }

    @Test void packetsWhereOnlySomeRaysEnterTheSceneOrStayActive() {
        TriangleMesh mesh = new MeshBuilder().mesh(Scenes.sphere(2, 2, 2, 1.5, 12, 24)).mesh(Scenes.gridCube(4, 1)).build();
        double[] rays = new double[6 * 64 * 4];
        SplittableRandom rnd = new SplittableRandom(3);
        for (int i = 0, k = 0; i < 64 * 4; i++) {
            boolean misses = i % 3 == 0;       // from beside the scene, pointing away from it: never active
            rays[k++] = misses ? 9 + rnd.nextDouble() : rnd.nextDouble(0.5, 3.5);
            rays[k++] = rnd.nextDouble(0.5, 3.5);
            rays[k++] = misses ? 9 : rnd.nextDouble(0.5, 3.5);
            rays[k++] = 0.3 + rnd.nextDouble(); rays[k++] = 0.2 + rnd.nextDouble(); rays[k++] = 0.1 + rnd.nextDouble();
        }
        agree(mesh, rays, 0, Double.POSITIVE_INFINITY);
        agree(mesh, rays, 0, 0.05);           // most rays end before any triangle: active only near their origins
        agree(mesh, rays, 0.4, 0.9);          // start late, end early: some rays blocked, others never tested
    }

    @Test void anEmptyPacketIsAnsweredWithNothingAndAnEmptyMeshWithMisses() {
        KdTree tree = Builders.create("sah").build(Scenes.gridCube(2, 1));
        RayPacket p = new RayPacket();
        tree.packetQuery().closestHits(p);
        tree.packetQuery().anyHits(p);
        assertThat(p.size()).isZero();
        KdTree empty = Builders.create("sah").build(new TriangleMesh(new double[0], new int[0]));
        p.add(0, 0, 0, 1, 1, 1, 0, Double.POSITIVE_INFINITY);
        empty.packetQuery().closestHits(p);
        assertThat(p.found(0)).isFalse();
        empty.packetQuery().anyHits(p);
        assertThat(p.found(0)).isFalse();
    }

    @Test void tracingPacketsAllocatesNothing() {
        var threads = java.lang.management.ManagementFactory.getThreadMXBean();
        org.junit.jupiter.api.Assumptions.assumeTrue(threads instanceof com.sun.management.ThreadMXBean, "needs allocation counting");
        var counting = (com.sun.management.ThreadMXBean) threads;
        TriangleMesh mesh = new MeshBuilder().mesh(Scenes.sphere(2, 2, 2, 1.5, 12, 24)).mesh(Scenes.gridCube(4, 1)).build();
        PacketQuery packets = Builders.create("sah").build(mesh).packetQuery();
        double[] coherent = tile(new double[] {2.1, 2.2, 9}, new double[] {2, 2, 0}, 2.5, 8);
        RayPacket p = new RayPacket();
        SplittableRandom rnd = new SplittableRandom(1);
        Runnable trace = () -> {
            for (int k = 0; k < 200; k++) {
                p.clear();
                for (int i = 0; i < 64; i++) {
                    boolean mixed = k % 2 == 1;         // every other packet of mixed octants, split by octant
                    p.add(coherent[6 * i], coherent[6 * i + 1], coherent[6 * i + 2], coherent[6 * i + 3] + (mixed ? rnd.nextDouble(-1, 1) : 0),
                            coherent[6 * i + 4], coherent[6 * i + 5], 0, Double.POSITIVE_INFINITY);
                }
                packets.closestHits(p);
                packets.anyHits(p);
            }
        };
        trace.run();
        long bytes = Long.MAX_VALUE;
        for (int run = 0; run < 20 && bytes >= 1024; run++) {
            long before = counting.getThreadAllocatedBytes(Thread.currentThread().getId());
            trace.run();
            bytes = Math.min(bytes, counting.getThreadAllocatedBytes(Thread.currentThread().getId()) - before);
        }
        assertThat(bytes).as("bytes allocated for 400 packets of 64 rays").isLessThan(1024L);
    }

    @Test void aNonFiniteOriginIsRefusedAsASingleRayIs() {
        KdTree tree = Builders.create("sah").build(Scenes.gridCube(2, 1));
        RayPacket p = new RayPacket();
        p.add(0.5, 0.5, 0.5, 1, 1, 1, 0, 1);
        p.add(Double.NaN, 0.5, 0.5, 1, 1, 1, 0, 1);
        assertThatThrownBy(() -> tree.packetQuery().closestHits(p)).isInstanceOf(IllegalArgumentException.class)
                .hasMessageContaining("non-finite origin");
        assertThatThrownBy(() -> tree.query().closestHit(p.ray(1, new Ray(3)), 0, 1, new Hit())).isInstanceOf(IllegalArgumentException.class);
    }
}
