package org.kdtree.check;

import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;
import org.kdtree.build.BuildContext;
import org.kdtree.build.BuildNode;
import org.kdtree.build.Children;
import org.kdtree.build.KdTreeBuilder;
import org.kdtree.build.MedianPlaneBuilder;
import org.kdtree.geom.SplitPlane;
import org.kdtree.shape.Primitives;
import org.kdtree.testing.TestScenes;

/** The contract's checks fail, with a useful message, on the mistakes students make. */
class ContractCatchesBrokenBuildersTest {
    private final Primitives scene = TestScenes.random2D(200, 3);

    /** Sends primitives crossing the plane to the left child only. */
    static final class ForgetsStraddlers extends MedianPlaneBuilder {
        @Override protected Children split(BuildContext c, BuildNode node, SplitPlane p) {
            Children full = super.split(c, node, p);
            int axis = p.axis();
            int[] keep = java.util.Arrays.stream(full.right().refs()).filter(r -> {
                for (int j = 0; j < node.size(); j++)
                    if (node.ref(j) == r) return node.clippedMin(j, axis) >= p.position();
                return true;
            }).toArray();
            int k = node.dimension();
            double[] clipped = new double[2 * k * keep.length];
            for (int i = 0; i < keep.length; i++)
                for (int j = 0; j < full.right().size(); j++)
                    if (full.right().ref(j) == keep[i])
                        System.arraycopy(full.right().clippedBounds(), 2 * k * j, clipped, 2 * k * i, 2 * k);
            return new Children(full.left(), new BuildNode(full.right().voxel(), keep, clipped, full.right().depth()));
        }
    }

    /** Puts every primitive in both children. */
    static final class SendsEverythingEverywhere extends MedianPlaneBuilder {
        @Override protected Children split(BuildContext c, BuildNode node, SplitPlane p) {
            Children full = super.split(c, node, p);
            BuildNode left = new BuildNode(full.left().voxel(), node.refs().clone(), node.clippedBounds().clone(), node.depth() + 1);
            return new Children(left, full.right());
        }
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
        KdTreeBuilder b = new ForgetsStraddlers();
        assertThatThrownBy(() -> TreeChecks.checkAll(b, scene, b.build(scene)))
                .isInstanceOf(ContractViolation.class)
                .hasMessageContaining("does not list it");
    }

    @Test void aPrimitiveListedInALeafItDoesNotTouchIsReported() {
        KdTreeBuilder b = new SendsEverythingEverywhere();
        assertThatThrownBy(() -> TreeChecks.checkAll(b, scene, b.build(scene)))
                .isInstanceOf(ContractViolation.class)
                .hasMessageContaining("does not touch that voxel");
    }

    @Test void theBaseClassEnforcesTheDepthCapEvenIfTerminateForgetsIt() {
        KdTreeBuilder b = new IgnoresDepth().maxDepth(4);
        // the tree is valid: the recursion itself stops at the cap
        TreeChecks.checkAll(b, TestScenes.identicalTriangles(50), b.build(TestScenes.identicalTriangles(50)));
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
                .isInstanceOf(org.kdtree.build.BuilderFault.class)
                .hasMessageContaining("outside the voxel");
    }
}
