package org.kdtree.build;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.constraints.IntRange;
import org.junit.jupiter.api.Test;
import org.kdtree.shape.Primitives;
import org.kdtree.testing.TestScenes;
import org.kdtree.testing.Trees;
import org.kdtree.tree.KdTree;

class SahBuilderTest {
    @Test void onClusteredScenesSahCostsLessThanBothMedianTrees() {
        for (Primitives scene : new Primitives[] {TestScenes.clustered2D(300, 11), TestScenes.clusteredTriangles(600, 12)}) {
            double sah = new SahBuilder().build(scene).stats().expectedCost();
            double medianPlane = new MedianPlaneBuilder().build(scene).stats().expectedCost();
            double objectMedian = new ObjectMedianBuilder().build(scene).stats().expectedCost();
            assertThat(sah).as("SAH vs median plane, %d-D", scene.dimension()).isLessThan(medianPlane);
            assertThat(sah).as("SAH vs object median, %d-D", scene.dimension()).isLessThan(objectMedian);
        }
    }

    @Property(tries = 25)
    void naiveAndSortedSearchesBuildTheSameTree(@ForAll @IntRange(min = 0, max = 120) int n, @ForAll long seed,
                                                @ForAll boolean threeD) {
        Primitives scene = threeD ? TestScenes.randomTriangles(n, 0.1, seed) : TestScenes.random2D(n, seed);
        KdTree naive = new SahBuilder().algorithm(SahBuilder.Algorithm.NAIVE).build(scene);
        KdTree sorted = new SahBuilder().algorithm(SahBuilder.Algorithm.SORTED).build(scene);
        Trees.assertSameTree(naive, sorted);
    }

    @Test void naiveAndSortedAgreeOnPlanarAndFlatScenes() {
        for (Primitives scene : new Primitives[] {TestScenes.cubeGrid(2), TestScenes.flatTriangles(200, 3),
                TestScenes.degenerateTriangles(), TestScenes.clustered2D(100, 5)}) {
            Trees.assertSameTree(new SahBuilder().algorithm(SahBuilder.Algorithm.NAIVE).build(scene),
                    new SahBuilder().algorithm(SahBuilder.Algorithm.SORTED).build(scene));
        }
    }

    /** terminate and findPlane stay the contract; what the SAH remembers between them is its own, not BuildNode's public API. */
    @Test void thePlaneRememberedBetweenTerminateAndFindPlaneIsNotPublic() {
        assertThat(java.util.Arrays.stream(BuildNode.class.getMethods()).map(java.lang.reflect.Method::getName))
                .doesNotContain("plan", "plannedPlane", "plannedCost", "choose", "chosen");
    }

    /** Each algorithm carries its own strategy: the exact ones and the binned one, with or without an engine, build the tree of their recursion. */
    @Test void everyAlgorithmsEngineBuildsTheTreeOfItsRecursion() {
        Primitives mesh = TestScenes.clusteredTriangles(3000, 5);
        for (SahBuilder.Algorithm a : SahBuilder.Algorithm.values()) {
            if (a == SahBuilder.Algorithm.NAIVE) continue; // O(N^2): SahAlgorithmsTest compares it on smaller scenes
            KdTree engine = new SahBuilder().algorithm(a).build(mesh);
            KdTree recursion = new SahBuilder() { }.algorithm(a).build(mesh); // a subclass always gets the recursion
            Trees.assertSameTree(engine, recursion);
            assertThat(a.hasEngine()).isEqualTo(a == SahBuilder.Algorithm.EVENT || a == SahBuilder.Algorithm.BINNED);
        }
    }

    @Test void aSinglePrimitiveIsALeaf() {
        KdTree tree = new SahBuilder().build(TestScenes.soup(new double[] {0, 0, 0, 1, 0, 0, 0, 1, 0}));
        assertThat(tree.nodeCount()).isEqualTo(1);
        assertThat(tree.leafSize(0)).isEqualTo(1);
    }

    @Test void higherTraversalCostMakesShallowerTrees() {
        Primitives scene = TestScenes.randomTriangles(500, 0.05, 9);
        int cheap = new SahBuilder().costs(1, 20).build(scene).nodeCount();
        int dear = new SahBuilder().costs(200, 20).build(scene).nodeCount();
        assertThat(dear).isLessThan(cheap);
    }

    @Test void depthCapIsRespected() {
        KdTree tree = new SahBuilder().maxDepth(3).build(TestScenes.randomTriangles(500, 0.01, 9));
        assertThat(tree.stats().maxDepth()).isLessThanOrEqualTo(3);
    }

    @Test void settingsAreChecked() {
        assertThatThrownBy(() -> new SahBuilder().emptyWeight(0)).hasMessageContaining("emptyWeight (lambda) must be between 0.01 and 1");
        assertThatThrownBy(() -> new SahBuilder().emptyWeight(1.5)).hasMessageContaining("got 1.5");
        assertThatThrownBy(() -> new SahBuilder().maxDepth(65)).hasMessageContaining("maxDepth must be between -1 and 64");
        assertThatThrownBy(() -> new SahBuilder().costs(-1, 20)).hasMessageContaining("Kt");
    }
}
