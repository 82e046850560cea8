package org.kdtree.gui;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.kdtree.generate.Shapes;
import org.kdtree.kdtree.KdTree;
import org.kdtree.shape.Scene2D;
import org.kdtree.shape.Shape2D;
import org.kdtree.spec.BuilderSpec;

/** The nearest-neighbour stepper's recording: the brute-force answer, and pruning that never cuts inside the k-th distance. */
class NearestRecorderTest {
    @Test void recordedSearchesEndWithTheBruteForceNeighbours() {
        Random r = new Random(7);
        int searches = 0;
        for (String b : CompareView.DEFAULT_BUILDERS) {
            for (List<Shape2D> shapes : List.of(Shapes.clustered(300, 5).shapes(), Shapes.uniform(250, 8).shapes(),
                    BuiltinScenes.talkFigures(), onGridWithDuplicates(200, r))) {
                Scene2D scene = new Scene2D(shapes);
                KdTree tree = BuilderSpec.of(b).create().build(scene);
                for (int i = 0; i < 60; i++) {
                    double[] q = {r.nextDouble() * 14 - 2, r.nextDouble() * 14 - 2};
                    int k = 1 + r.nextInt(i % 3 == 0 ? 64 : 8);
                    NearestTrace t = NearestRecorder.record(tree, scene, q, k);
                    List<NearestTrace.Neighbour> expected = NearestBruteForce.nearest(scene, q, k);
                    assertThat(t.result()).as("%s, k = %d, q = (%f, %f)", b, k, q[0], q[1]).isEqualTo(expected);
                    checkSteps(t, scene.size());
                    searches++;
                }
            }
        }
        assertThat(searches).isEqualTo(3 * 4 * 60);
    }

    /** Pruned voxels lie at or beyond the k-th distance of their step; the list only shrinks its radius; counts agree. */
    private static void checkSteps(NearestTrace t, int objects) {
        NearestTrace.Step last = t.step(t.size() - 1);
        assertThat(t.step(0).kind()).isEqualTo(NearestTrace.Kind.BEGIN);
        assertThat(last.kind()).isEqualTo(NearestTrace.Kind.END);
        assertThat(last.best()).isEqualTo(t.result());
        double radius = Double.POSITIVE_INFINITY;
        long pruned = 0, tests = 0, entered = 0;
        java.util.BitSet tested = new java.util.BitSet();
        for (NearestTrace.Step s : t.steps()) {
            assertThat(s.kth()).as("the search radius never grows").isLessThanOrEqualTo(radius);
            radius = s.kth();
            assertThat(s.best()).hasSizeLessThanOrEqualTo(t.k());
            switch (s.kind()) {
                case PRUNE -> {
                    pruned++;
                    assertThat(s.bound()).as("a pruned node's voxel distance").isGreaterThanOrEqualTo(s.kth());
                }
                case INTERIOR, LEAF -> {
                    entered++;
                    assertThat(s.bound()).isLessThanOrEqualTo(s.kth() * (1 + 1e-9));
                }
                case TEST -> {
                    tests++;
                    assertThat(tested.get(s.object())).as("each object is tested once").isFalse();
                    tested.set(s.object());
                    if (s.improved()) assertThat(s.best()).contains(new NearestTrace.Neighbour(s.object(), s.distance()));
                }
                case MAILBOXED -> assertThat(tested.get(s.object())).isTrue();
                default -> { }
            }
        }
        assertThat(pruned).isEqualTo(t.pruned());
        assertThat(tests).isEqualTo(t.tests()).isLessThanOrEqualTo(objects);
        assertThat(entered).isEqualTo(t.nodes());
    }

    @Test void theSearchPrunesAndTestsFewerObjectsThanTheScene() {
        Scene2D scene = new Scene2D(Shapes.uniform(400, 3).shapes());
        KdTree tree = BuilderSpec.of("sah").create().build(scene);
        NearestTrace t = NearestRecorder.record(tree, scene, new double[] {5, 5}, 3);
        assertThat(t.pruned()).isPositive();
        assertThat(t.tests()).isLessThan(scene.size() / 4);
        assertThat(t.enteredUpTo(t.size() - 1).cardinality()).isEqualTo((int) t.nodes());
        assertThat(t.prunedUpTo(t.size() - 1).cardinality()).isEqualTo((int) t.pruned());
        assertThat(NearestRecorder.record(tree, scene, null, 3).size()).isZero();
    }

    @Test void aQueryInsideAFilledShapeFindsItAtDistanceZeroAndFlatShapesAreNeverNeighbours() {
        List<Shape2D> shapes = List.of(new Shape2D.Rect(0, 0, 2, 2), new Shape2D.Rect(3, 3, 3, 5),
                new Shape2D.Segment(4, 0, 4, 4), new Shape2D.Point(6, 1));
        Scene2D scene = new Scene2D(shapes);
        KdTree tree = BuilderSpec.of("sah").create().build(scene);
        NearestTrace t = NearestRecorder.record(tree, scene, new double[] {1, 1}, 4);
        assertThat(t.result()).extracting(NearestTrace.Neighbour::object).containsExactly(0, 2, 3);
        assertThat(t.result().get(0).distance()).isZero();
        assertThat(t.result().get(1).distance()).isEqualTo(3.0);
    }

    /** Points, segments, rectangles (some flat) and triangles on a grid of halves, with duplicates for ties. */
    private static List<Shape2D> onGridWithDuplicates(int n, Random r) {
        List<Shape2D> out = new java.util.ArrayList<>();
        while (out.size() < n) {
            double x = Math.floor(r.nextDouble() * 20) / 2, y = Math.floor(r.nextDouble() * 20) / 2;
            switch (r.nextInt(5)) {
                case 0 -> out.add(new Shape2D.Point(x, y));
                case 1 -> out.add(new Shape2D.Segment(x, y, x + r.nextDouble(), y - r.nextDouble()));
                case 2 -> out.add(new Shape2D.Rect(x, y, x + r.nextDouble() * 0.5, y + (r.nextBoolean() ? 0 : 0.3)));
                case 3 -> out.add(new Shape2D.Triangle(x, y, x + 0.4, y, x + 0.2, y + 0.3));
                default -> out.add(out.isEmpty() ? new Shape2D.Point(x, y) : out.get(r.nextInt(out.size())));
            }
        }
        return out;
    }
}
