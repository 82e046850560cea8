package org.kdtree.bvh;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.kdtree.accel.TreeStats;
import org.kdtree.generate.Meshes;
import org.kdtree.generate.Shapes;
import org.kdtree.io.PrimitivesReader;
import org.kdtree.shape.Primitives;
import org.kdtree.shape.TriangleMesh;

/**
 * The build makes the same hierarchy, bit for bit, as the one recorded in
 * {@code hierarchy-signatures.txt}: per scene and settings, the node count, depth, leaf order,
 * links, leaf sizes and box doubles (hashed) and the expected cost. The scenes take every path of
 * the build: 3-D meshes (the unrolled loops), 2-D shapes (the general ones), slivers (boxes of
 * zero area), coincident centroids and a chain held by the depth cap (the median
 * cut), threads. A change to the build that is meant to keep the tree must keep this file.
 */
class BvhSignatureTest {
    private static final Path RECORDED = Path.of("src/test/resources/org/kdtree/bvh/hierarchy-signatures.txt");

    @Test void theBuildMakesTheRecordedHierarchies() throws IOException {
        TriangleMesh spheres = PrimitivesReader.readMesh(Path.of("scenes/clustered-spheres.obj"));
        List<String> got = new ArrayList<>();
        got.add(signature("clustered-spheres", spheres, new BvhBuilder()));
        got.add(signature("clustered-spheres threads 4", spheres, new BvhBuilder().threads(4)));
        got.add(signature("clustered-spheres leaf 4 bins 8", spheres, new BvhBuilder().leafSize(4).bins(8)));
        got.add(signature("clustered-spheres depth 12", spheres, new BvhBuilder().maxDepth(12)));
        got.add(signature("uniform 3000", Meshes.uniform(3000, 1), new BvhBuilder()));
        got.add(signature("clustered 40000 threads 2", Meshes.clustered(40_000, 7), new BvhBuilder().threads(2)));
        got.add(signature("flat 500", Meshes.flat(500, 3), new BvhBuilder()));
        got.add(signature("planar and degenerate", Meshes.planarAndDegenerate(4), new BvhBuilder()));
        got.add(signature("surface 20000 bins 64", Meshes.surface(20_000, 3), new BvhBuilder().bins(64)));
        for (int cap : new int[] {-1, 12, 3}) got.add(signature("chain depth " + cap, BvhTest.chain(2000), new BvhBuilder().maxDepth(cap)));
        got.add(signature("2-D mixed", Shapes.mixed(400, 5), new BvhBuilder()));
        got.add(signature("2-D clustered leaf 2", Shapes.clustered(3000, 6), new BvhBuilder().leafSize(2)));
        got.add(signature("2-D overlapping threads 2", Shapes.overlapping(6000, 8), new BvhBuilder().threads(2)));
        got.add(signature("2-D aligned depth 6", Shapes.aligned(800, 9), new BvhBuilder().maxDepth(6)));
        got.add(signature("2-D long thin bins 4", Shapes.longThin(), new BvhBuilder().bins(4)));
        got.add(signature("3-D slivers on a line", slivers(500, false), new BvhBuilder()));
        got.add(signature("3-D slivers at one point", slivers(100, true), new BvhBuilder().leafSize(1)));
        assertThat(got).containsExactlyElementsOf(Files.readAllLines(RECORDED, StandardCharsets.UTF_8));
    }

    /** Triangles of zero area along the x axis, or all at the origin: boxes of zero area, centroids that may coincide. */
    private static TriangleMesh slivers(int n, boolean atOnePoint) {
        double[] v = new double[9 * n];
        int[] idx = new int[3 * n];
        for (int i = 0; i < n; i++) {
            double x = atOnePoint ? 0 : i * 0.37 % 11;
            System.arraycopy(new double[] {x, 0, 0, x + 0.5, 0, 0, x + 0.25, 0, 0}, 0, v, 9 * i, 9);
            for (int c = 0; c < 3; c++) idx[3 * i + c] = 3 * i + c;
        }
        return new TriangleMesh(v, idx);
    }

    private static String signature(String name, Primitives p, BvhBuilder builder) {
        Bvh h = builder.build(p);
        int nodes = h.nodeCount(), k = p.dimension();
        ByteBuffer bytes = ByteBuffer.allocate(nodes * (8 + 16 * k) + 4 * h.primitiveCount());
        for (int node = 0; node < nodes; node++) {
            bytes.putInt(h.isLeaf(node) ? ~h.leafStart(node) : h.left(node)).putInt(h.isLeaf(node) ? h.leafSize(node) : 0);
            for (int a = 0; a < k; a++) bytes.putLong(Double.doubleToRawLongBits(h.min(node, a))).putLong(Double.doubleToRawLongBits(h.max(node, a)));
        }
        for (int r = 0; r < h.primitiveCount(); r++) bytes.putInt(h.primitive(r));
        TreeStats s = h.stats();
        return name + ": nodes " + nodes + ", leaves " + s.leaves() + ", depth " + h.maxDepth() + ", primitives " + h.primitiveCount()
                + ", expected cost " + s.expectedCost() + ", sha-256 " + sha256(bytes.array());
    }

    private static String sha256(byte[] bytes) {
        try {
            return HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256").digest(bytes)).substring(0, 24);
        } catch (NoSuchAlgorithmException e) {
            throw new AssertionError(e);
        }
    }
}
