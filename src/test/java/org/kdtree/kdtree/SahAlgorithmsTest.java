package org.kdtree.kdtree;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.kdtree.generate.Meshes;
import org.kdtree.generate.Shapes;
import org.kdtree.shape.Primitives;

/** NAIVE, SORTED and EVENT must build the very same tree: same splits, same leaves, same order of references. */
class SahAlgorithmsTest {
    static Stream<Arguments> scenes() {
        return Stream.of(
                Arguments.of("random 3-D", Meshes.uniform(300, 0.2, 1)),
                Arguments.of("random 3-D, large triangles", Meshes.uniform(200, 0.8, 2)),
                Arguments.of("clustered", Meshes.clustered(400, 0.02, 3)),
                Arguments.of("bumpy sphere", Meshes.surface(12, 20, 4)),
                Arguments.of("planar and degenerate", Meshes.planarAndDegenerate(5)),
                Arguments.of("random 2-D", Shapes.aligned(300, 6)),
                Arguments.of("random 2-D, small", Shapes.aligned(40, 7)));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("scenes")
    void naiveSortedAndEventBuildTheSameTree(String name, Primitives scene) {
        for (boolean perfect : new boolean[] {true, false}) {
            for (double lambda : new double[] {0.8, 1.0}) {
                KdTree naive = build(scene, SahBuilder.Algorithm.NAIVE, perfect, lambda);
                KdTree sorted = build(scene, SahBuilder.Algorithm.SORTED, perfect, lambda);
                KdTree event = build(scene, SahBuilder.Algorithm.EVENT, perfect, lambda);
                assertThat(naive.nodeCount()).as("%s splits somewhere", name).isGreaterThan(1);
                assertSameTree(sorted, naive, name + " sorted perfect=" + perfect + " lambda=" + lambda);
                assertSameTree(event, naive, name + " event perfect=" + perfect + " lambda=" + lambda);
            }
        }
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("scenes")
    void eventBuildHonoursTheDepthCap(String name, Primitives scene) {
        KdTree event = new SahBuilder().algorithm(SahBuilder.Algorithm.EVENT).maxDepth(3).build(scene);
        assertSameTree(event, new SahBuilder().algorithm(SahBuilder.Algorithm.NAIVE).maxDepth(3).build(scene));
        assertThat(event.stats().maxDepth()).isLessThanOrEqualTo(3);
    }

    /** A real (bundled) scene of 10,370 triangles: too big for NAIVE in a unit test, so SORTED is the reference. */
    @org.junit.jupiter.api.Test
    void sortedAndEventBuildTheSameTreeOnTheBundledScene() throws java.io.IOException {
        Primitives scene = org.kdtree.io.PrimitivesReader.readMesh(java.nio.file.Path.of("scenes/clustered-spheres.obj"));
        KdTree sorted = new SahBuilder().algorithm(SahBuilder.Algorithm.SORTED).build(scene);
        assertThat(sorted.nodeCount()).isGreaterThan(1000);
        assertSameTree(new SahBuilder().algorithm(SahBuilder.Algorithm.EVENT).build(scene), sorted, "clustered-spheres");
    }

    static KdTree build(Primitives scene, SahBuilder.Algorithm a, boolean perfect, double lambda) {
        return new SahBuilder().algorithm(a).lambda(lambda).perfectSplits(perfect).build(scene);
    }

    static void assertSameTree(KdTree actual, KdTree expected) {
        assertSameTree(actual, expected, "");
    }

    static void assertSameTree(KdTree actual, KdTree expected, String what) {
        org.kdtree.testing.Trees.assertSameTree(expected, actual, what);
    }
}
