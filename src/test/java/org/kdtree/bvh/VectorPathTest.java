package org.kdtree.bvh;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.kdtree.accel.Hit;
import org.kdtree.accel.PacketQuery;
import org.kdtree.accel.RayPacket;
import org.kdtree.accel.RayQuery;
import org.kdtree.accel.Vectorization;
import org.kdtree.accel.TriangleIntersector;
import org.kdtree.generate.HardMeshes;
import org.kdtree.generate.Meshes;
import org.kdtree.geom.Ray;
import org.kdtree.shape.TriangleMesh;

/**
 * The BVH's loops on whichever path this JVM takes (the Vector API kernels on JDK 21 or newer with
 * {@code jdk.incubator.vector}, as CI's second test run has it; else the Java 17 ones), bit for
 * bit: the single-ray loop against the listening loop, the packet loop against the single-ray
 * loop, on random rays, rays from far away, rays grazing box faces and aimed at shared vertices
 * and edges. The kernels themselves, each against its specification: {@link RayKernelTest} and
 * {@link PacketKernelTest}. It checks that the JVM says which path it takes.
 */
class VectorPathTest {
    @Test void theJvmSaysWhichPath() {
        boolean vectorJdk = Runtime.version().feature() >= Vectorization.JDK
                && ModuleLayer.boot().findModule(Vectorization.MODULE).isPresent() && !"false".equals(System.getProperty("kdtree.vector"));
        assertThat(Vectorization.enabled()).isEqualTo(vectorJdk);
        assertThat(WideTraversal.KERNEL instanceof ScalarRayKernel).isEqualTo(!vectorJdk);
        assertThat(PacketTraversal.KERNEL instanceof ScalarPacketKernel).isEqualTo(!vectorJdk);
        assertThat(Vectorization.describe()).startsWith(vectorJdk ? "vector" : "scalar");
    }

    /**
     * The single-ray loop, over whichever kernels this JVM chose, against the listening loop: the
     * same hits, bit for bit, bar the triangle named when two are hit at the very same t (the fast
     * loop keeps the lower leaf position, the listening one the lower index).
     */
    @Test void theSingleRayLoopGivesTheListeningLoopsHits() {
        for (TriangleMesh mesh : List.of(Meshes.clustered(3000, 1), Meshes.surface(2000, 2), HardMeshes.cubeGrid(6),
                Meshes.planarAndDegenerate(3), HardMeshes.scaled(HardMeshes.cubeGrid(3), 1e30), HardMeshes.scaled(Meshes.clustered(500, 4), 1e-30))) {
            Bvh bvh = new BvhBuilder().build(mesh);
            TriangleIntersector tris = new TriangleIntersector(mesh);
            RayQuery fast = new WideTraversal(bvh);
            RayQuery listening = new BvhTraverser(bvh, org.kdtree.accel.TraversalListener.NONE);
            Random rnd = new Random(17);
            Ray ray = new Ray(3);
            Hit a = new Hit(), b = new Hit(), c = new Hit();
            var box = bvh.bounds();
            for (int n = 0; n < 20_000; n++) {
                double[] o = new double[3], d = new double[3];
                for (int k = 0; k < 3; k++) {
                    double lo = box.min(k), ext = box.max(k) - lo;
                    switch (n % 4) {
                        case 0 -> o[k] = lo + rnd.nextDouble() * ext;                         // inside
                        case 1 -> o[k] = lo + (rnd.nextDouble() - 0.5) * ext * 1e6;          // far away
                        case 2 -> o[k] = rnd.nextBoolean() ? box.min(k) : box.max(k);        // on the box's faces
                        default -> o[k] = lo + Math.floor(rnd.nextDouble() * 8) * ext / 8;   // on a lattice
                    }
                    d[k] = rnd.nextGaussian();
                }
                if (n % 4 == 1) for (int k = 0; k < 3; k++) d[k] = box.min(k) + rnd.nextDouble() * (box.max(k) - box.min(k)) - o[k];
                ray.set(o[0], o[1], o[2], d[0], d[1], d[2]);
                double tMin = n % 7 == 0 ? rnd.nextDouble() : 0, tMax = n % 5 == 0 ? 1 + rnd.nextDouble() * 10 : Double.POSITIVE_INFINITY;
                boolean fa = fast.closestHit(ray, tMin, tMax, a), fb = listening.closestHit(ray, tMin, tMax, b);
                String what = mesh.size() + " triangles, ray " + ray + " [" + tMin + ", " + tMax + "]";
                assertThat(fa).as(what).isEqualTo(fb);
                assertThat(Double.doubleToLongBits(a.t)).as(what).isEqualTo(Double.doubleToLongBits(b.t));
                if (a.primitive != b.primitive) {   // a tie: the other triangle is hit at the same t
                    assertThat(tris.intersect(a.primitive, ray, tMin, tMax, c.reset())).as(what).isTrue();
                    assertThat(Double.doubleToLongBits(c.t)).as(what).isEqualTo(Double.doubleToLongBits(b.t));
                } else {
                    assertThat(a.u).as(what).isEqualTo(b.u);
                    assertThat(a.v).as(what).isEqualTo(b.v);
                }
                assertThat(fast.anyHit(ray, tMin, tMax)).as(what).isEqualTo(fb);
            }
        }
    }

    /**
     * The packet loop against single rays, bit for bit: packets of a shared
     * origin (a camera's), of spread origins (shadow rays, any hit), of a size below the vectors'
     * 64 rays (the vector path sends those one by one), and of rays whose sheared frames differ (one ray at a time).
     */
    @Test void packetsGiveEachRayItsSingleAnswer() {
        for (TriangleMesh mesh : List.of(Meshes.clustered(3000, 1), Meshes.surface(2000, 2), HardMeshes.cubeGrid(6),
                HardMeshes.scaled(Meshes.clustered(500, 4), 1e-30))) {
            Bvh bvh = new BvhBuilder().build(mesh);
            RayQuery single = new WideTraversal(bvh);
            PacketQuery packets = new PacketTraversal(bvh, single);
            var box = bvh.bounds();
            Random rnd = new Random(23);
            RayPacket p = new RayPacket();
            for (int n = 0; n < 400; n++) {
                p.clear();
                int size = n % 5 == 4 ? 1 + rnd.nextInt(RayPacket.CAPACITY - 1) : RayPacket.CAPACITY;
                double[] eye = new double[3], aim = new double[3];
                for (int k = 0; k < 3; k++) {
                    eye[k] = box.min(k) - (box.max(k) - box.min(k)) * (0.2 + rnd.nextDouble());
                    aim[k] = box.min(k) + rnd.nextDouble() * (box.max(k) - box.min(k));
                }
                // Spread within a tile, or (every third packet) across the diagonal where the largest direction component changes.
                double spread = n % 3 == 0 ? 0.6 : 0.02;
                boolean sharedOrigin = n % 2 == 0;
                for (int i = 0; i < size; i++) {
                    double[] o = eye.clone();
                    if (!sharedOrigin) for (int k = 0; k < 3; k++) o[k] += rnd.nextDouble() * 1e-2 * (box.max(k) - box.min(k));
                    double dx = aim[0] - o[0] + spread * (i % 8 - 3.5) / 8 * (box.max(0) - box.min(0));
                    double dy = aim[1] - o[1] + spread * (i / 8 - 3.5) / 8 * (box.max(1) - box.min(1));
                    double dz = aim[2] - o[2];
                    p.add(o[0], o[1], o[2], dx, dy, dz, n % 7 == 0 ? 0.5 : 0, n % 4 == 0 ? 1 + rnd.nextDouble() : Double.POSITIVE_INFINITY);
                }
                packets.closestHits(p);
                Ray ray = new Ray(3);
                Hit hit = new Hit();
                for (int i = 0; i < size; i++) {
                    boolean found = single.closestHit(p.ray(i, ray), p.tMin[i], p.tMax[i], hit);
                    String what = mesh.size() + " triangles, packet " + n + ", ray " + ray + " [" + p.tMin[i] + ", " + p.tMax[i] + "]";
                    assertThat(p.found(i)).as(what).isEqualTo(found);
                    assertThat(p.primitive[i]).as(what).isEqualTo(hit.primitive);
                    assertThat(Double.doubleToLongBits(p.t[i])).as(what).isEqualTo(Double.doubleToLongBits(hit.t));
                    assertThat(p.u[i]).as(what).isEqualTo(hit.u);
                    assertThat(p.v[i]).as(what).isEqualTo(hit.v);
                }
                packets.anyHits(p);
                for (int i = 0; i < size; i++)
                    assertThat(p.found(i)).as("any hit, packet " + n + ", ray " + p.ray(i, ray))
                            .isEqualTo(single.anyHit(ray, p.tMin[i], p.tMax[i]));
            }
        }
    }
}
