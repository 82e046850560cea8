package org.kdtree.kdtree;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.constraints.IntRange;
import org.junit.jupiter.api.Test;
import org.kdtree.generate.HardMeshes;
import org.kdtree.generate.Meshes;
import org.kdtree.generate.Shapes;
import org.kdtree.shape.Primitives;
import org.kdtree.testing.Trees;

class SahBuilderTest {
    @Test void onClusteredScenesSahCostsLessThanBothMedianTrees() {
        for (Primitives scene : new Primitives[] {Shapes.clustered(300, 11), Meshes.cornerClusters(600, 12)}) {
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
        Primitives scene = threeD ? Meshes.uniform(n, 0.1, seed) : Shapes.mixed(n, seed);
        KdTree naive = new SahBuilder().algorithm(SahBuilder.Algorithm.NAIVE).build(scene);
        KdTree sorted = new SahBuilder().algorithm(SahBuilder.Algorithm.SORTED).build(scene);
        Trees.assertSameTree(naive, sorted);
    }

    @Test void naiveAndSortedAgreeOnPlanarAndFlatScenes() {
        for (Primitives scene : new Primitives[] {HardMeshes.cubeGrid(2), Meshes.flat(200, 3),
                HardMeshes.degenerate(), Shapes.clustered(100, 5)}) {
            Trees.assertSameTree(new SahBuilder().algorithm(SahBuilder.Algorithm.NAIVE).build(scene),
                    new SahBuilder().algorithm(SahBuilder.Algorithm.SORTED).build(scene));
        }
    }

    /** What terminate finds, findPlane returns: the SAH searches once per node, never again in findPlane. */
    @Test void findPlaneReturnsWhatTerminateFoundWithoutSearchingAgain() {
        int[] finds = {0}, again = {0};
        boolean[] inFind = {false};
        SahBuilder counting = new SahBuilder() {
            @Override protected boolean terminate(BuildContext c, BuildNode n) {
                if (inFind[0]) again[0]++;
                return super.terminate(c, n);
            }

            @Override protected org.kdtree.geom.SplitPlane findPlane(BuildContext c, BuildNode n) {
                finds[0]++;
                inFind[0] = true;
                try {
                    return super.findPlane(c, n);
                } finally {
                    inFind[0] = false;
                }
            }
        };
        KdTree tree = counting.build(Meshes.cornerClusters(500, 5));
        assertThat(finds[0]).as("findPlane calls").isGreaterThan(100).isEqualTo((tree.nodeCount() - 1) / 2);
        assertThat(again[0]).as("searches again in findPlane").isZero();
    }

    /**
     * A student's SAH written with the public API only (BuildNode.keepPlane, SahCost, SahSplit, a
     * public plane search) builds the library's tree: keepPlane carries terminate's plane to findPlane.
     */
    static final class KeepingSah extends KdTreeBuilder {
        @Override public String name() { return "keeping-sah"; }

        @Override protected boolean terminate(BuildContext context, BuildNode node) {
            if (node.size() == 0) return true;
            SahCost sah = new SahCost(costModel(), 0.8, node.voxel());
            if (!(sah.halfArea() > 0)) return true;
            SahSplit best = new SahSplit();
            new SortedPlaneSearch().search(node, sah, best);
            if (!best.found() || best.cost() >= sah.leafCost(node.size())) return true;
            node.keepPlane(best.plane());
            return false;
        }

        @Override protected org.kdtree.geom.SplitPlane findPlane(BuildContext context, BuildNode node) {
            return node.keptPlane();
        }
    }

    @Test void aStudentsSahWithKeepPlaneBuildsTheLibrarysTree() throws Exception {
        assertThat(BuildNode.class.getMethod("keepPlane", org.kdtree.geom.SplitPlane.class)).isNotNull();
        Primitives mesh = Meshes.cornerClusters(2000, 6);
        Trees.assertSameTree(new SahBuilder().build(mesh), new KeepingSah().build(mesh));
    }

    /** A subclass of the SAH runs on the same store and searches as the SAH itself: the same tree, whatever the algorithm. */
    @Test void aSubclassBuildsTheSahsTreeWithEveryAlgorithm() {
        Primitives mesh = Meshes.cornerClusters(3000, 5);
        for (SahBuilder.Algorithm a : SahBuilder.Algorithm.values()) {
            if (a == SahBuilder.Algorithm.NAIVE) continue; // O(N^2): SahAlgorithmsTest compares it on smaller scenes
            KdTree own = new SahBuilder().algorithm(a).build(mesh);
            KdTree subclass = new SahBuilder() { }.algorithm(a).build(mesh);
            Trees.assertSameTree(own, subclass);
        }
    }

    @Test void aSinglePrimitiveIsALeaf() {
        KdTree tree = new SahBuilder().build(HardMeshes.soup(new double[] {0, 0, 0, 1, 0, 0, 0, 1, 0}));
        assertThat(tree.nodeCount()).isEqualTo(1);
        assertThat(tree.leafSize(0)).isEqualTo(1);
    }

    @Test void higherTraversalCostMakesShallowerTrees() {
        Primitives scene = Meshes.uniform(500, 0.05, 9);
        int cheap = new SahBuilder().costs(1, 20).build(scene).nodeCount();
        int dear = new SahBuilder().costs(200, 20).build(scene).nodeCount();
        assertThat(dear).isLessThan(cheap);
    }

    @Test void depthCapIsRespected() {
        KdTree tree = new SahBuilder().maxDepth(3).build(Meshes.uniform(500, 0.01, 9));
        assertThat(tree.stats().maxDepth()).isLessThanOrEqualTo(3);
    }

    @Test void settingsAreChecked() {
        assertThatThrownBy(() -> new SahBuilder().lambda(0)).hasMessageContaining("lambda must be between 0.01 and 1");
        assertThatThrownBy(() -> new SahBuilder().lambda(1.5)).hasMessageContaining("got 1.5");
        assertThatThrownBy(() -> new SahBuilder().maxDepth(65)).hasMessageContaining("Kmaxdepth must be between -1 and 64");
        assertThatThrownBy(() -> new SahBuilder().costs(-1, 20)).hasMessageContaining("Kt");
    }
}
