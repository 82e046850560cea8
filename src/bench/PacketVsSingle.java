import java.nio.file.Path;
import java.util.Arrays;
import org.kdtree.accel.AccelerationStructure;
import org.kdtree.generate.MeshGrid;
import org.kdtree.io.PrimitivesReader;
import org.kdtree.measure.RayBatch;
import org.kdtree.measure.RaySet;
import org.kdtree.shape.TriangleMesh;
import org.kdtree.spec.Builders;

/**
 * The benchmark's set P (1024 x 1024 primary rays) through the kd-tree's packet loop (8 x 8 tiles)
 * against the same rays one at a time through its single-ray loop, in one JVM, alternating, after
 * 3 warm-up rounds; the checksums must agree. Prints medians and the median of the per-round ratios.
 * Run from the project folder after a build (on JDK 21+ add --add-modules jdk.incubator.vector for
 * the vector kernels):
 *   java -cp target/kdtree.jar src/bench/PacketVsSingle.java MESH.obj GRID ROUNDS
 * (GRID: the mesh repeated GRID x GRID on the x-z plane, 1 for the mesh alone.)
 */
public class PacketVsSingle {
    public static void main(String[] a) throws Exception {
        TriangleMesh m = PrimitivesReader.readMesh(Path.of(a[0]));
        int grid = Integer.parseInt(a[1]), rounds = Integer.parseInt(a[2]);
        if (grid > 1) m = MeshGrid.grid(m, grid);
        AccelerationStructure tree = (AccelerationStructure) Builders.create("sah").build(m);
        RaySet p = RaySet.primary(m, RaySet.SPEC_IMAGE);
        System.err.println("# " + m.size() + " triangles; path: " + tree.describePath());
        double[] packets = new double[rounds], singles = new double[rounds], ratio = new double[rounds];
        try (RayBatch inPackets = new RayBatch(1, tree); RayBatch alone = new RayBatch(1, tree::query)) {
            for (int w = 0; w < 3; w++) { inPackets.trace(p); alone.trace(p); }
            for (int r = 0; r < rounds; r++) {
                long t0 = System.nanoTime();
                RayBatch.Checksum c1 = inPackets.trace(p);
                long t1 = System.nanoTime();
                RayBatch.Checksum c2 = alone.trace(p);
                long t2 = System.nanoTime();
                if (!c1.equals(c2)) throw new AssertionError("packets " + c1 + ", single rays " + c2);
                packets[r] = (t1 - t0) / 1e6;
                singles[r] = (t2 - t1) / 1e6;
                ratio[r] = singles[r] / packets[r];
            }
            System.err.println("# checksum " + inPackets.trace(p));
        }
        Arrays.sort(packets);
        Arrays.sort(singles);
        Arrays.sort(ratio);
        System.out.printf("P in packets %.1f ms (%.2f Mrays/s), single rays %.1f ms (%.2f Mrays/s); single/packet time, median of %d rounds %.2f (%.2f-%.2f)%n",
                packets[rounds / 2], p.size() / packets[rounds / 2] / 1e3, singles[rounds / 2], p.size() / singles[rounds / 2] / 1e3,
                rounds, ratio[rounds / 2], ratio[0], ratio[rounds - 1]);
    }
}
