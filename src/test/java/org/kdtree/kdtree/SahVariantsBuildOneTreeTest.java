package org.kdtree.kdtree;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.kdtree.generate.Meshes;
import org.kdtree.generate.Shapes;
import org.kdtree.shape.PointsKd;
import org.kdtree.shape.Primitives;
import org.kdtree.shape.TriangleMesh;

/**
 * The SAH builds one tree whatever path a node takes through the node store: a subclass of
 * {@link SahBuilder} and the builder itself, one thread or two, nodes turned into events at the
 * root (EVENT) or below a size (BINNED's {@code exactBelow}), with and without perfect splits,
 * under a binding reference budget.
 */
class SahVariantsBuildOneTreeTest {
    static Stream<Arguments> scenes() {
        return Stream.of(
                Arguments.of("random 3-D", Meshes.uniform(600, 0.2, 31)),
                Arguments.of("clustered", Meshes.clustered(3000, 0.02, 32)),
                Arguments.of("bumpy sphere", Meshes.surface(30, 40, 33)),
                Arguments.of("planar and degenerate", Meshes.planarAndDegenerate(34)),
                Arguments.of("random 2-D", Shapes.aligned(800, 35)),
                Arguments.of("planes on bin boundaries", planesOnBinBoundaries()),
                Arguments.of("points in 5-D", pointsIn5D()));
    }

    /** Clustered points in five dimensions, some repeated: the store and the searches are k-dimensional. */
    static PointsKd pointsIn5D() {
        java.util.Random r = new java.util.Random(37);
        double[] c = new double[5 * 1500];
        for (int i = 0; i < 1500; i++)
            for (int a = 0; a < 5; a++) c[5 * i + a] = i % 10 == 9 ? c[5 * (i - 1) + a] : (i % 3) + 0.2 * r.nextGaussian();
        return new PointsKd(5, c);
    }

    /**
     * Layers of flat squares at z = 1 .. 7 in the box [0, 8]^3, where 16 bins put boundaries,
     * among tilted triangles: binned planes fall on planar primitives, whose side matters.
     */
    static TriangleMesh planesOnBinBoundaries() {
        java.util.Random r = new java.util.Random(36);
        java.util.List<Double> v = new java.util.ArrayList<>();
        for (int z = 1; z < 8; z++)
            for (int i = 0; i < 8; i++) {
                double x = i, y = r.nextInt(8);
                for (double c : new double[] {x, y, z, x + 1, y, z, x, y + 1, z}) v.add(c);
            }
        for (int i = 0; i < 300; i++) {
            double x = 7 * r.nextDouble(), y = 7 * r.nextDouble(), z = 7 * r.nextDouble();
            for (double c : new double[] {x, y, z, x + 1, y, z + 0.5, x, y + 1, z + 1}) v.add(c);
        }
        for (double c : new double[] {0, 0, 0, 8, 8, 8, 0, 8, 0}) v.add(c);
        double[] vertices = v.stream().mapToDouble(Double::doubleValue).toArray();
        int[] indices = new int[vertices.length / 3];
        for (int i = 0; i < indices.length; i++) indices[i] = i;
        return new TriangleMesh(vertices, indices);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("scenes")
    void binnedSubclassAndThreads(String name, Primitives scene) {
        for (int exactBelow : new int[] {0, 16, 64}) {
            for (boolean perfect : new boolean[] {true, false}) {
                SahBuilder own = binned(new SahBuilder(), exactBelow, perfect);
                SahBuilder recursion = binned(new SahBuilder() {}, exactBelow, perfect);
                KdTree expected = recursion.build(scene);
                assertThat(expected.nodeCount()).as("%s splits", name).isGreaterThan(8);
                SahAlgorithmsTest.assertSameTree(own.build(scene), expected,
                        name + " exactBelow=" + exactBelow + " perfect=" + perfect);
                SahAlgorithmsTest.assertSameTree(own.threads(2).build(scene), expected, name + " 2 threads");
            }
        }
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("scenes")
    void eventSubclassAndThreads(String name, Primitives scene) {
        for (boolean perfect : new boolean[] {true, false}) {
            KdTree expected = new SahBuilder() {}.algorithm(SahBuilder.Algorithm.EVENT).perfectSplits(perfect).build(scene);
            SahAlgorithmsTest.assertSameTree(new SahBuilder().perfectSplits(perfect).build(scene), expected, name);
            SahAlgorithmsTest.assertSameTree(new SahBuilder().perfectSplits(perfect).maxDepth(6).threads(2).build(scene),
                    new SahBuilder() {}.perfectSplits(perfect).maxDepth(6).build(scene), name + " depth 6, 2 threads");
        }
    }

    /**
     * A budget of 2 references per primitive binds on every scene with straddlers (points never
     * straddle): every path cuts the tree at the same nodes.
     */
    @ParameterizedTest(name = "{0}")
    @MethodSource("scenes")
    void aBindingReferenceBudgetCutsTheSameTree(String name, Primitives scene) {
        KdTree expected = new SahBuilder() {}.referenceBudget(2).build(scene);
        if (!(scene instanceof PointsKd)) assertThat(expected.budgetLeaves()).as("%s: the budget binds", name).isPositive();
        assertThat(expected.refArray().length).isLessThanOrEqualTo(2 * scene.size());
        for (int threads : new int[] {1, 2}) {
            KdTree event = new SahBuilder().referenceBudget(2).threads(threads).build(scene);
            SahAlgorithmsTest.assertSameTree(event, expected, name + " event, threads " + threads);
            assertThat(event.budgetLeaves()).isEqualTo(expected.budgetLeaves());
        }
        KdTree binned = binned(new SahBuilder(), 16, true).referenceBudget(2).build(scene);
        SahAlgorithmsTest.assertSameTree(binned, binned(new SahBuilder() {}, 16, true).referenceBudget(2).build(scene), name + " binned");
    }

    private static SahBuilder binned(SahBuilder b, int exactBelow, boolean perfect) {
        b.algorithm(SahBuilder.Algorithm.BINNED).bins(16).exactBelow(exactBelow).perfectSplits(perfect);
        return b;
    }
}
