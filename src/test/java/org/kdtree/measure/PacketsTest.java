package org.kdtree.measure;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.kdtree.accel.AccelerationStructure;
import org.kdtree.accel.Hit;
import org.kdtree.accel.PacketQuery;
import org.kdtree.accel.RayPacket;
import org.kdtree.accel.RayQuery;
import org.kdtree.accel.TriangleIntersector;
import org.kdtree.bvh.BvhBuilder;
import org.kdtree.generate.Meshes;
import org.kdtree.geom.Ray;
import org.kdtree.spec.Builders;
import org.kdtree.shape.TriangleMesh;

/**
 * Packets give every ray its single-ray answer, bit for bit (primitive, t, u, v; and for any-hit
 * queries, whether it is blocked), through every structure's packet query (the BVH's packet loop,
 * the kd-tree's): camera tiles on generated meshes, rays aimed exactly at shared
 * vertices and edges of a lattice (ties between triangles), cut intervals, and packets that mix
 * direction signs (split into one packet per octant of directions, a ray with a zero direction
 * component traced alone).
 */
class PacketsTest {
    private static List<AccelerationStructure> structures(TriangleMesh mesh) {
        List<AccelerationStructure> all = new ArrayList<>();
        all.add(new BvhBuilder().build(mesh));
        all.add(new BvhBuilder().width(2).build(mesh));
        all.add(new BvhBuilder().width(8).leafSize(4).build(mesh));
        all.add(Builders.create("sah").build(mesh));             // every structure answers packets in a packet loop
        return all;
    }

    /** A lattice of unit squares in z = 0, two triangles each: every vertex and diagonal is shared. */
    static TriangleMesh lattice(int n) {
        double[] v = new double[3 * (n + 1) * (n + 1)];
        for (int j = 0, at = 0; j <= n; j++)
            for (int i = 0; i <= n; i++) { v[at++] = i; v[at++] = j; v[at++] = 0; }
        int[] f = new int[6 * n * n];
        for (int j = 0, at = 0; j < n; j++)
            for (int i = 0; i < n; i++) {
                int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
                f[at++] = a; f[at++] = b; f[at++] = d;
                f[at++] = a; f[at++] = d; f[at++] = c;
            }
        return new TriangleMesh(v, f);
    }

    @Test void cameraTilesOnGeneratedMeshes() {
        for (TriangleMesh mesh : List.of(Meshes.clustered(3000, 7), Meshes.uniform(2000, 3), Meshes.surface(2000, 5))) {
            RaySet p = RaySet.primary(mesh, 64);
            for (AccelerationStructure s : structures(mesh)) agree(s, mesh, p.rays(), 64, 0, Double.POSITIVE_INFINITY);
        }
    }

    @Test void raysThroughSharedVerticesAndEdges() {
        TriangleMesh mesh = lattice(12);
        // A camera above the lattice aimed at lattice points and edge midpoints: every ray hits a shared vertex or edge.
        int w = 24;
        double[] rays = new double[6 * w * w];
        for (int j = 0, at = 0; j < w; j++)
            for (int i = 0; i < w; i++) {
                double tx = i * 0.5, ty = j * 0.5;
                rays[at++] = 3.25; rays[at++] = 2.75; rays[at++] = 9;
                rays[at++] = tx - 3.25; rays[at++] = ty - 2.75; rays[at++] = -9;
            }
        for (AccelerationStructure s : structures(mesh)) {
            agree(s, mesh, rays, w, 0, Double.POSITIVE_INFINITY);
            agree(s, mesh, rays, w, 0.5, 1.0);             // the hit at t = 1 exactly, on the interval's end
            agree(s, mesh, rays, w, 1.0, 3.0);
        }
    }

    @Test void randomAndMixedSignPackets() {
        TriangleMesh mesh = Meshes.clustered(2000, 11);
        Random rnd = new Random(5);
        double[] rays = new double[6 * 64 * 16];
        for (int i = 0; i < rays.length; i += 6) {
            for (int a = 0; a < 3; a++) rays[i + a] = rnd.nextDouble() * 2 - 0.5;
            for (int a = 0; a < 3; a++) rays[i + 3 + a] = rnd.nextGaussian();
            if (i % 60 == 0) rays[i + 3] = 0;            // a zero component: the packet goes one by one
        }
        for (AccelerationStructure s : structures(mesh)) agree(s, mesh, rays, 64, 0, Double.POSITIVE_INFINITY);
    }

    @Test void shadowRaysTowardALight() {
        // As a renderer's: from points spread over a patch below the scene toward one small square above it, ending short of it.
        TriangleMesh mesh = Meshes.clustered(3000, 13);
        Random rnd = new Random(8);
        double[] rays = new double[6 * 64 * 64];
        for (int i = 0, at = 0; i < 64 * 64; i++) {
            double x = (i % 64) / 6.4 + rnd.nextDouble() * 0.1, z = (i / 64) / 6.4, y = -0.5;     // the clusters lie in [0, 10]^3
            double lx = 4 + rnd.nextDouble() * 2, ly = 12, lz = 4 + rnd.nextDouble() * 2;
            rays[at++] = x; rays[at++] = y; rays[at++] = z;
            rays[at++] = lx - x; rays[at++] = ly - y; rays[at++] = lz - z;
        }
        for (AccelerationStructure s : structures(mesh)) {
            agree(s, mesh, rays, 64, 0, 1 - 1e-7);
            agree(s, mesh, rays, 64, 0, 0.5);
        }
    }

    /** Traces the image's rays in 8 x 8 tiles as packets and one by one; every answer the same bits. */
    private static void agree(AccelerationStructure s, TriangleMesh mesh, double[] rays, int w, double tMin, double tMax) {
        TriangleIntersector tris = new TriangleIntersector(mesh);
        PacketQuery pq = s.packetQuery();
        assertThat(pq.tracesTogether()).as(s.kind() + ": a packet loop").isTrue();
        RayQuery single = s.query();
        RayPacket packet = new RayPacket();
        Ray ray = new Ray(3);
        Hit hit = new Hit();
        int h = rays.length / 6 / w, hits = 0;
        for (int y0 = 0; y0 < h; y0 += 8)
            for (int x0 = 0; x0 < w; x0 += 8) {
                packet.clear();
                for (int y = y0; y < Math.min(h, y0 + 8); y++)
                    for (int x = x0; x < Math.min(w, x0 + 8); x++) {
                        int o = 6 * (y * w + x);
                        packet.add(rays[o], rays[o + 1], rays[o + 2], rays[o + 3], rays[o + 4], rays[o + 5], tMin, tMax);
                    }
                pq.closestHits(packet);
                for (int i = 0; i < packet.size(); i++) {
                    boolean found = single.closestHit(packet.ray(i, ray), tMin, tMax, hit);
                    String what = s.kind() + " " + s.stats() + " ray " + ray + " [" + tMin + ", " + tMax + "]";
                    assertThat(packet.found(i)).as(what).isEqualTo(found);
                    assertThat(packet.primitive[i]).as(what).isEqualTo(hit.primitive);
                    assertThat(Double.doubleToLongBits(packet.t[i])).as(what).isEqualTo(Double.doubleToLongBits(hit.t));
                    assertThat(packet.u[i]).as(what).isEqualTo(hit.u);
                    assertThat(packet.v[i]).as(what).isEqualTo(hit.v);
                    if (found) hits++;
                }
                // The same packet's any-hit answers (shadow rays): each exactly the single ray's.
                pq.anyHits(packet);
                for (int i = 0; i < packet.size(); i++)
                    assertThat(packet.found(i)).as(s.kind() + " any hit, ray " + packet.ray(i, ray) + " [" + tMin + ", " + tMax + "]")
                            .isEqualTo(single.anyHit(ray, tMin, tMax));
            }
        assertThat(hits).as(s.kind() + ": the rays hit something").isPositive();
    }
}
