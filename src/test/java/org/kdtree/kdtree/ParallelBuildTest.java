package org.kdtree.kdtree;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;
import org.kdtree.generate.Meshes;
import org.kdtree.shape.TriangleMesh;

/** A build with several threads makes the very tree of the sequential build. */
class ParallelBuildTest {
    private static final TriangleMesh SPHERE = Meshes.surface(40, 70, 11);       // 5,600 triangles
    private static final TriangleMesh CLUSTERS = Meshes.clustered(5000, 0.02, 12);

    @Test void eventSahWithTwoAndThreeThreadsBuildsTheSequentialTree() {
        for (TriangleMesh scene : new TriangleMesh[] {SPHERE, CLUSTERS}) {
            KdTree one = new SahBuilder().build(scene);
            assertThat(one.nodeCount()).isGreaterThan(1000);
            SahAlgorithmsTest.assertSameTree(new SahBuilder().threads(2).build(scene), one);
            SahAlgorithmsTest.assertSameTree(new SahBuilder().threads(3).build(scene), one);
        }
    }

    @Test void otherBuildersAndAlgorithmsToo() {
        KdTreeBuilder[] builders = {
                new SahBuilder().algorithm(SahBuilder.Algorithm.SORTED),
                new SahBuilder().algorithm(SahBuilder.Algorithm.BINNED),
                new SahBuilder().perfectSplits(false),
                new MedianPlaneBuilder(),
                new ObjectMedianBuilder()};
        for (KdTreeBuilder b : builders) {
            KdTree one = b.threads(1).build(SPHERE);
            SahAlgorithmsTest.assertSameTree(b.threads(2).build(SPHERE), one);
        }
    }

    @Test void rejectsNonsenseThreadCounts() {
        assertThatThrownBy(() -> new SahBuilder().threads(0)).isInstanceOf(IllegalArgumentException.class);
        assertThat(new SahBuilder().threads(4).describeSettings()).contains("threads=4");
    }
}
