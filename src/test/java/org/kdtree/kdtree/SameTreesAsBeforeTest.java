package org.kdtree.kdtree;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Supplier;
import org.junit.jupiter.api.Test;
import org.kdtree.check.CourseScenes;
import org.kdtree.examples.CentreMidpointBuilder;
import org.kdtree.generate.HardMeshes;
import org.kdtree.generate.Meshes;
import org.kdtree.generate.Shapes;
import org.kdtree.io.BundledScenes;
import org.kdtree.shape.Primitives;

/**
 * Every builder, under many settings, builds the very tree it built before the recursion was
 * written once (issue 22): a golden master. {@code tree-fingerprints.txt} holds, per scene and
 * builder, the node count, the budget leaves and 64-bit hashes of the node array, the leaf
 * references and the root voxel, as commit 667a597 built them. It was written by this test with
 * {@code -Dkdtree.writeFingerprints=src/test/resources/org/kdtree/build/tree-fingerprints.txt};
 * rewrite it only for a change that is meant to change trees, and say so in the commit.
 */
class SameTreesAsBeforeTest {
    private static final String RESOURCE = "tree-fingerprints.txt";

    /**
     * The course scenes renamed since the golden file was written, by the name it gives them: the
     * scenes are the same, their names now say which generated scene they are.
     */
    private static final Map<String, String> COURSE_NAMES_IN_THE_FILE = Map.of(
            "mixed 2-D shapes", "random 2-D shapes", "corner clusters", "clustered triangles");

    /**
     * The scenes, under the labels the golden file gives them: generated in code (the 2-D
     * "random" one is {@link Shapes#aligned}), small enough for the naive search, and the course's.
     */
    static Map<String, Primitives> scenes() {
        Map<String, Primitives> s = new LinkedHashMap<>();
        s.put("random 3-D", Meshes.uniform(400, 0.2, 31));
        s.put("clustered", Meshes.clustered(1500, 0.02, 32));
        s.put("bumpy sphere", Meshes.surface(20, 30, 33));
        s.put("planar and degenerate", Meshes.planarAndDegenerate(34));
        s.put("random 2-D", Shapes.aligned(500, 35));
        s.put("planes on bin boundaries", SahVariantsBuildOneTreeTest.planesOnBinBoundaries());
        s.put("points in 5-D", SahVariantsBuildOneTreeTest.pointsIn5D());
        s.put("talk figures", BundledScenes.read2D("talk-figures.scene2d"));
        s.put("identical triangles", HardMeshes.identical(2000));
        s.put("cube grid", HardMeshes.cubeGrid(3));
        s.put("degenerate triangles", HardMeshes.degenerate());
        for (CourseScenes.Named c : CourseScenes.all())
            s.put("course " + COURSE_NAMES_IN_THE_FILE.getOrDefault(c.name(), c.name()), c.primitives());
        return s;
    }

    /** The builders and settings: every algorithm, the safety nets, threads, and subclasses. */
    static Map<String, Supplier<KdTreeBuilder>> builders() {
        Map<String, Supplier<KdTreeBuilder>> b = new LinkedHashMap<>();
        b.put("median-plane", MedianPlaneBuilder::new);
        b.put("median-plane minPrims=0 maxDepth=12", () -> new MedianPlaneBuilder().minPrimitives(0).maxDepth(12));
        b.put("median-plane no perfect splits", () -> new MedianPlaneBuilder().perfectSplits(false));
        b.put("object-median", ObjectMedianBuilder::new);
        b.put("object-median budget 2", () -> new ObjectMedianBuilder().referenceBudget(2));
        b.put("sliding-midpoint", SlidingMidpointBuilder::new);
        b.put("sliding-midpoint leaf 1", () -> new SlidingMidpointBuilder().leafSize(1));
        b.put("centre-midpoint", CentreMidpointBuilder::new);
        b.put("sah", SahBuilder::new);
        b.put("sah 2 threads", () -> new SahBuilder().threads(2));
        b.put("sah subclass", () -> new SahBuilder() {});
        b.put("sah no perfect splits", () -> new SahBuilder().perfectSplits(false));
        b.put("sah budget 2", () -> new SahBuilder().referenceBudget(2));
        b.put("sah lambda 1 kt 1 ki 0.5", () -> new SahBuilder().lambda(1).costs(1, 0.5));
        b.put("sah maxDepth 6", () -> new SahBuilder().maxDepth(6));
        b.put("sah fast", () -> new SahBuilder().depthFactor(0.8));   // the old preset FAST: a depth cap 8 + 0.8 log2 N
        b.put("sah sorted", () -> new SahBuilder().algorithm(SahBuilder.Algorithm.SORTED));
        b.put("sah naive", () -> new SahBuilder().algorithm(SahBuilder.Algorithm.NAIVE));
        b.put("sah binned", () -> new SahBuilder().algorithm(SahBuilder.Algorithm.BINNED));
        b.put("sah binned 16 exactBelow 0", () -> new SahBuilder().algorithm(SahBuilder.Algorithm.BINNED).bins(16).exactBelow(0));
        b.put("sah binned 16 exactBelow 16 no perfect", () -> new SahBuilder().algorithm(SahBuilder.Algorithm.BINNED).bins(16)
                .exactBelow(16).perfectSplits(false));
        b.put("sah binned 2 threads", () -> new SahBuilder().algorithm(SahBuilder.Algorithm.BINNED).exactBelow(16).threads(2));
        return b;
    }

    @Test
    void everyBuilderBuildsTheTreeItBuiltBefore() throws IOException {
        List<String> lines = new ArrayList<>();
        for (Map.Entry<String, Primitives> s : scenes().entrySet())
            for (Map.Entry<String, Supplier<KdTreeBuilder>> b : builders().entrySet())
                lines.add(s.getKey() + " | " + b.getKey() + " | " + fingerprint(b.getValue().get().build(s.getValue())));
        String write = System.getProperty("kdtree.writeFingerprints");
        if (write != null) {
            Files.write(Path.of(write), lines, StandardCharsets.UTF_8);
            return;
        }
        List<String> expected;
        try (InputStream in = getClass().getResourceAsStream(RESOURCE)) {
            assertThat(in).as(RESOURCE).isNotNull();
            expected = new String(in.readAllBytes(), StandardCharsets.UTF_8).lines().toList();
        }
        assertThat(lines).hasSameSizeAs(expected);
        for (int i = 0; i < lines.size(); i++) assertThat(lines.get(i)).isEqualTo(expected.get(i));
    }

    /** Node count, budget leaves, and hashes of nodes, references and the root voxel. */
    static String fingerprint(KdTree t) {
        double[] box = new double[2 * t.dimension()];
        for (int a = 0; a < t.dimension(); a++) {
            box[a] = t.bounds().min(a);
            box[t.dimension() + a] = t.bounds().max(a);
        }
        long boxHash = 1125899906842597L;
        for (double x : box) boxHash = mix(boxHash, Double.doubleToLongBits(x));
        return t.nodeCount() + " nodes, " + t.budgetLeaves() + " budget leaves, nodes " + Long.toHexString(hash(t.nodeArray()))
                + ", refs " + Long.toHexString(hash(t.refArray())) + ", voxel " + Long.toHexString(boxHash);
    }

    private static long hash(int[] a) {
        long h = 1125899906842597L;
        for (int x : a) h = mix(h, x);
        return mix(h, a.length);
    }

    private static long mix(long h, long x) {
        h ^= x;
        h *= 0x9E3779B97F4A7C15L;
        return h ^ (h >>> 29);
    }
}
