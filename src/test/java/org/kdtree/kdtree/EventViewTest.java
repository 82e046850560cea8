package org.kdtree.kdtree;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.kdtree.generate.Meshes;
import org.kdtree.geom.Box;
import org.kdtree.geom.SplitPlane;
import org.kdtree.shape.Primitives;
import org.kdtree.shape.TriangleMesh;

/**
 * The student's view of a node's sorted events ({@link BuildNode#eventCount},
 * {@link BuildNode#eventPosition}, {@link BuildNode#eventKind}, {@link BuildNode#eventPrimitive}),
 * which the handout teaches, checked against events made independently: each of the node's
 * primitives clipped to the node's voxel by the geometry itself ({@link Primitives#clip}), a
 * start at its minimum and an end at its maximum on each axis, or one planar event where they
 * are equal. At the root the events are sorted from the bounds; below it the library's
 * O(N log N) split keeps them sorted (the builder splits every node it reads, so every node
 * below the root is made by that split).
 */
class EventViewTest {
    /** Events on a plane may differ by the clipper's conservative padding, a few units in the last place. */
    private static final double CLOSE = 1e-9;

    @Test void theEventViewListsEachNodesClippedBoundsInOrder() {
        for (TriangleMesh scene : new TriangleMesh[] {Meshes.uniform(600, 0.1, 51), Meshes.flat(300, 52), Meshes.surface(12, 16, 53)}) {
            EventReader reader = new EventReader();
            reader.build(scene);
            assertThat(reader.wrong).as("events that differ from the clipped bounds").isEmpty();
            assertThat(reader.nodes).as("nodes read").isGreaterThan(30);
            assertThat(reader.events).as("events read").isGreaterThan(6L * scene.size());
        }
    }

    /** The flat scene's triangles all lie in z = 0.5: every one of their events on z is planar, on x and y none is. */
    @Test void aFlatSceneHasPlanarEventsOnItsFlatAxisOnly() {
        EventReader reader = new EventReader();
        reader.build(Meshes.flat(300, 52));
        assertThat(reader.wrong).isEmpty();
        assertThat(reader.planar).as("planar events").isPositive();
        assertThat(reader.planarOffAxis).as("planar events off the flat axis").isZero();
    }

    /** One event as the view lists it, or as the geometry gives it. */
    private record Event(double position, int kind, int primitive) {
    }

    /**
     * A student's builder that reads every node's events through the view and splits each node
     * in the middle of its voxel, cycling the axes, down to depth 6.
     */
    private static final class EventReader extends KdTreeBuilder {
        final List<String> wrong = new ArrayList<>();
        int nodes, planar, planarOffAxis;
        long events;

        @Override public String name() { return "event-reader"; }

        @Override protected boolean terminate(BuildContext context, BuildNode node) {
            nodes++;
            check(context.primitives(), node);
            return node.size() <= 2 || node.depth() >= 6;
        }

        @Override protected SplitPlane findPlane(BuildContext context, BuildNode node) {
            Box v = node.voxel();
            int axis = node.depth() % node.dimension();
            return new SplitPlane(axis, (v.min(axis) + v.max(axis)) / 2);
        }

        private void check(Primitives prims, BuildNode node) {
            int k = node.dimension(), n = node.size();
            int[] refs = new int[n];
            for (int j = 0; j < n; j++) refs[j] = node.ref(j);
            Box voxel = node.voxel().copy(), part = new Box(k);
            for (int axis = 0; axis < k; axis++) {
                List<Event> listed = new ArrayList<>(), expected = new ArrayList<>();
                for (int i = 0; i < node.eventCount(axis); i++) {
                    listed.add(new Event(node.eventPosition(axis, i), node.eventKind(axis, i), node.eventPrimitive(axis, i)));
                    if (i > 0 && listed.get(i).position() < listed.get(i - 1).position())
                        wrong.add(where(node, axis) + "event " + i + " before event " + (i - 1));
                }
                for (int p : refs) {
                    prims.clip(p, voxel, part);
                    double lo = part.min(axis), hi = part.max(axis);
                    if (lo == hi) expected.add(new Event(lo, BuildNode.PLANAR, p));
                    else {
                        expected.add(new Event(lo, BuildNode.START, p));
                        expected.add(new Event(hi, BuildNode.END, p));
                    }
                }
                events += listed.size();
                for (Event e : listed) if (e.kind() == BuildNode.PLANAR) {
                    planar++;
                    if (axis != 2) planarOffAxis++;
                }
                compare(node, axis, listed, expected);
            }
        }

        /** The same events, primitive by primitive and kind by kind, at positions equal to within {@link #CLOSE}. */
        private void compare(BuildNode node, int axis, List<Event> listed, List<Event> expected) {
            Comparator<Event> order = Comparator.comparingInt(Event::primitive).thenComparingInt(Event::kind);
            listed.sort(order);
            expected.sort(order);
            if (listed.size() != expected.size()) {
                wrong.add(where(node, axis) + listed.size() + " events listed, " + expected.size() + " expected");
                return;
            }
            for (int i = 0; i < listed.size(); i++) {
                Event a = listed.get(i), b = expected.get(i);
                if (a.primitive() != b.primitive() || a.kind() != b.kind() || Math.abs(a.position() - b.position()) > CLOSE)
                    wrong.add(where(node, axis) + "listed " + a + ", expected " + b);
            }
        }

        private static String where(BuildNode node, int axis) {
            return "depth " + node.depth() + ", " + node.size() + " references, axis " + axis + ": ";
        }
    }
}
