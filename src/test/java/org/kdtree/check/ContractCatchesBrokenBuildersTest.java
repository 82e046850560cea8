package org.kdtree.check;

import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;
import org.kdtree.generate.HardMeshes;
import org.kdtree.generate.Shapes;
import org.kdtree.geom.SplitPlane;
import org.kdtree.kdtree.BuildContext;
import org.kdtree.kdtree.BuildNode;
import org.kdtree.kdtree.KdTree;
import org.kdtree.kdtree.KdTreeBuilder;
import org.kdtree.kdtree.KdTreeWriter;
import org.kdtree.kdtree.MedianPlaneBuilder;
import org.kdtree.shape.Primitives;

/** The contract's checks fail, with a useful message, on the mistakes students make. */
class ContractCatchesBrokenBuildersTest {
    private final Primitives scene = Shapes.mixed(200, 3);

    /**
     * The median plane's tree with its leaves rewritten by {@code leaf} (node, references -> references):
     * what a broken partition would have built. A builder can no longer partition for itself (the
     * recursion does), but the checks must still catch such trees.
     */
    private KdTree rewritten(KdTree tree, java.util.function.BiFunction<Integer, int[], int[]> leaf) {
        KdTreeWriter out = new KdTreeWriter(tree.dimension());
        copy(tree, 0, out, leaf);
        return out.finish(scene, tree.bounds(), tree.costModel(), tree.builderName());
    }

    private static void copy(KdTree tree, int node, KdTreeWriter out, java.util.function.BiFunction<Integer, int[], int[]> leaf) {
        if (tree.isLeaf(node)) {
            int[] refs = leaf.apply(node, tree.leafPrimitives(node));
            out.leaf(refs, 0, refs.length);
            return;
        }
        int interior = out.interior(tree.axis(node), tree.split(node));
        copy(tree, tree.leftChild(node), out, leaf);
        out.setRightChild(interior);
        copy(tree, tree.rightChild(node), out, leaf);
    }

    /** Ignores the depth cap it was given. */
    static final class IgnoresDepth extends KdTreeBuilder {
        @Override public String name() { return "ignores-depth"; }
        @Override protected boolean terminate(BuildContext c, BuildNode n) { return n.size() <= 1; }
        @Override protected SplitPlane findPlane(BuildContext c, BuildNode n) {
            int axis = n.depth() % n.dimension();
            return new SplitPlane(axis, n.voxel().min(axis) + 0.5 * n.voxel().extent(axis));
        }
    }

    /** Chooses a plane outside the voxel. */
    static final class PlaneOutside extends MedianPlaneBuilder {
        @Override protected SplitPlane findPlane(BuildContext c, BuildNode n) {
            return new SplitPlane(0, n.voxel().max(0) + 1);
        }
    }

    @Test void aPrimitiveMissingFromALeafItCrossesIsReported() {
        KdTreeBuilder b = new MedianPlaneBuilder();
        java.util.Set<Integer> seen = new java.util.HashSet<>();
        KdTree forgets = rewritten(b.build(scene), (node, refs) ->   // each primitive only in the first leaf that lists it
                java.util.Arrays.stream(refs).filter(seen::add).toArray());
        assertThatThrownBy(() -> TreeChecks.checkAll(b, scene, forgets))
                .isInstanceOf(ContractViolation.class)
                .hasMessageContaining("does not list it");
    }

    @Test void aPrimitiveListedInALeafItDoesNotTouchIsReported() {
        KdTreeBuilder b = new MedianPlaneBuilder();
        int[] all = java.util.stream.IntStream.range(0, scene.size()).toArray();
        boolean[] first = {true};
        KdTree everywhere = rewritten(b.build(scene), (node, refs) -> { // the first leaf lists every primitive
            boolean me = first[0];
            first[0] = false;
            return me ? all : refs;
        });
        assertThatThrownBy(() -> TreeChecks.checkAll(b, scene, everywhere))
                .isInstanceOf(ContractViolation.class)
                .hasMessageContaining("does not touch that voxel");
    }

    @Test void theBaseClassEnforcesTheDepthCapEvenIfTerminateForgetsIt() {
        KdTreeBuilder b = new IgnoresDepth().maxDepth(4);
        // the tree is valid: the recursion itself stops at the cap
        TreeChecks.checkAll(b, HardMeshes.identical(50), b.build(HardMeshes.identical(50)));
        TreeChecks.checkAll(b, scene, b.build(scene));
    }

    /** Leaves stopping to the depth cap. */
    static final class NeverStops extends KdTreeBuilder {
        @Override public String name() { return "never-stops"; }
        @Override protected boolean terminate(BuildContext c, BuildNode n) { return false; }
        @Override protected SplitPlane findPlane(BuildContext c, BuildNode n) {
            int axis = n.depth() % n.dimension();
            return new SplitPlane(axis, n.voxel().min(axis) + 0.5 * n.voxel().extent(axis));
        }
    }

    @Test void aBuilderThatNeverStopsIsReportedByTheContract() {
        ContractCase stops = Contract.cases().stream().filter(c -> c.name().startsWith("stops")).findFirst().orElseThrow();
        assertThatThrownBy(() -> stops.run(NeverStops::new))
                .isInstanceOf(ContractViolation.class)
                .hasMessageContaining("never-stops never stops")
                .hasMessageContaining("nodes holding no primitive, down to the depth cap");
        stops.run(MedianPlaneBuilder::new);
    }

    @Test void aPlaneOutsideTheVoxelIsAViolationOfTheContract() {
        assertThatThrownBy(() -> Contract.check(new PlaneOutside(), scene, "200 shapes"))
                .isInstanceOf(ContractViolation.class)
                .hasMessageContaining("outside the voxel")
                .hasMessageContaining("findPlane must return a plane");
    }

    @Test void aPlaneOutsideTheVoxelIsReportedByTheBuild() {
        assertThatThrownBy(() -> new PlaneOutside().build(scene))
                .isInstanceOf(org.kdtree.kdtree.BuilderFault.class)
                .hasMessageContaining("outside the voxel");
    }
}
