package org.kdtree.measure;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.kdtree.accel.AccelerationStructure;
import org.kdtree.accel.BruteForce;
import org.kdtree.accel.Hit;
import org.kdtree.accel.TriangleIntersector;
import org.kdtree.bvh.BvhBuilder;
import org.kdtree.generate.Meshes;
import org.kdtree.geom.Ray;
import org.kdtree.shape.TriangleMesh;
import org.kdtree.spec.Builders;

/**
 * Both structures are traced by the same kind of loop: given the structure, an image's rays (set
 * P) go in packets through its packet loop, other sets one ray at a time; the checksums are brute force's either way, and those of single rays.
 */
class RayBatchTest {
    @Test void everyStructureTracesAnImageInPacketsWithBruteForcesChecksum() {
        TriangleMesh mesh = Meshes.clustered(1500, 3);
        RaySet p = RaySet.primary(mesh, 48), r = RaySet.random(mesh, 5000);
        RayBatch.Checksum wantP = bruteForce(mesh, p), wantR = bruteForce(mesh, r);
        for (AccelerationStructure s : List.of(Builders.create("sah").build(mesh), new BvhBuilder().build(mesh))) {
            try (RayBatch packets = new RayBatch(2, s); RayBatch single = new RayBatch(2, s::query)) {
                assertThat(packets.trace(p)).as(s.kind() + " P in packets").isEqualTo(wantP);
                assertThat(single.trace(p)).as(s.kind() + " P one ray at a time").isEqualTo(wantP);
                assertThat(packets.trace(r)).as(s.kind() + " R").isEqualTo(wantR);
                assertThat(packets.describeLoops()).contains("(set P) in 8 x 8 packets").endsWith("through the packet loop");
                assertThat(single.describeLoops()).isEqualTo("every ray alone, through the single-ray loop");
            }
        }
    }

    /** The checksum by brute force, summed in blocks of 4096 rays as the batch sums it. */
    private static RayBatch.Checksum bruteForce(TriangleMesh mesh, RaySet set) {
        BruteForce brute = new BruteForce(new TriangleIntersector(mesh));
        double[] rs = set.rays();
        Ray ray = new Ray(3);
        Hit hit = new Hit();
        long hits = 0;
        double sum = 0;
        for (int b = 0; b < rs.length; b += 6 * 4096) {
            long h = 0;
            double s = 0;
            for (int o = b; o < Math.min(rs.length, b + 6 * 4096); o += 6) {
                ray.set(rs[o], rs[o + 1], rs[o + 2], rs[o + 3], rs[o + 4], rs[o + 5]);
                if (brute.closestHit(ray, RayBatch.T_MIN, Double.POSITIVE_INFINITY, hit)) {
                    h++;
                    s += hit.t;
                }
            }
            hits += h;
            sum += s;
        }
        return new RayBatch.Checksum(hits, sum);
    }
}
