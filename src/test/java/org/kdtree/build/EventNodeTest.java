package org.kdtree.build;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;
import org.kdtree.geom.Box;
import org.kdtree.geom.SplitPlane;
import org.kdtree.shape.Primitives;

/**
 * An event node keeps its clipped bounds only as events. What it recovers from them, and what its
 * split writes into the arena, must be exactly what the default partition computes.
 */
class EventNodeTest {
    private final Primitives scene = Scenes.randomTriangles(300, 0.4, 11);

    @Test void clippedBoundsAreRecoveredFromTheEvents() {
        BuildNode plain = root();
        EventNode events = EventNode.of(plain, false);
        assertSameReferencesAndBounds(events, plain, "root");
    }

    @Test void anEventSplitMakesTheChildrenOfTheDefaultPartition() {
        BuildNode r = root();
        for (int axis = 0; axis < 3; axis++) {
            // where the SAH puts planes: at a reference's bounds (an end, a start); and in between
            double[] planes = {r.clippedMax(7, axis), r.clippedMin(11, axis), (r.voxel().min(axis) + r.voxel().max(axis)) / 2};
            for (int i = 0; i < 6; i++) {
                boolean planarLeft = i % 2 == 0;
                BuildNode plain = root();
                SplitPlane p = new SplitPlane(axis, planes[i / 2], planarLeft);
                for (boolean perfect : new boolean[] {true, false}) {
                    Children expected = Partition.split(scene, plain, p, perfect);
                    Children actual = EventPartition.split(scene, EventNode.of(root(), false), p, perfect);
                    String what = p + " perfect=" + perfect;
                    assertThat(expected.left().size() + expected.right().size()).as(what + ": something straddles")
                            .isGreaterThan(plain.size());
                    assertSameReferencesAndBounds(actual.left(), expected.left(), what + " left");
                    assertSameReferencesAndBounds(actual.right(), expected.right(), what + " right");
                    assertSorted((EventNode) actual.left(), what + " left");
                    assertSorted((EventNode) actual.right(), what + " right");
                }
            }
        }
    }

    @Test void grandchildrenToo() {
        BuildNode plain = root();
        EventNode events = EventNode.of(root(), false);
        SplitPlane first = new SplitPlane(0, 0.1, true), second = new SplitPlane(2, -0.2, false);
        BuildNode expected = Partition.split(scene, Partition.split(scene, plain, first, true).right(), second, true).left();
        Children c = EventPartition.split(scene, events, first, true);
        BuildNode actual = EventPartition.split(scene, (EventNode) c.right(), second, true).left();
        assertSameReferencesAndBounds(actual, expected, "right, then left");
    }

    private BuildNode root() {
        KdTreeBuilder b = new SahBuilder().algorithm(SahBuilder.Algorithm.SORTED);
        return b.makeRoot(scene, scene.bounds());
    }

    private static void assertSameReferencesAndBounds(BuildNode actual, BuildNode expected, String what) {
        assertThat(actual.refs()).as(what + ": references").containsExactly(expected.refs());
        int k = expected.dimension();
        for (int j = 0; j < expected.size(); j++) {
            for (int a = 0; a < k; a++) {
                assertThat(bits(actual.clippedMin(j, a))).as("%s: min %d of reference %d", what, a, j)
                        .isEqualTo(bits(expected.clippedMin(j, a)));
                assertThat(bits(actual.clippedMax(j, a))).as("%s: max %d of reference %d", what, a, j)
                        .isEqualTo(bits(expected.clippedMax(j, a)));
            }
        }
        Box v = actual.voxel(), w = expected.voxel();
        for (int a = 0; a < k; a++) assertThat(v.min(a) == w.min(a) && v.max(a) == w.max(a)).as(what + ": voxel").isTrue();
    }

    private static void assertSorted(EventNode node, String what) {
        for (int a = 0; a < node.dimension(); a++)
            for (int e = node.eventsFrom(a) + 1; e < node.eventsTo(a); e++)
                assertThat(node.positions()[e]).as("%s: events of axis %d in order", what, a)
                        .isGreaterThanOrEqualTo(node.positions()[e - 1]);
    }

    private static long bits(double x) {
        return Double.doubleToRawLongBits(x);
    }
}
