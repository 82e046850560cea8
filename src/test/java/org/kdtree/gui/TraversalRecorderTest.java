package org.kdtree.gui;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Random;
import org.junit.jupiter.api.Test;
import org.kdtree.accel.BruteForce;
import org.kdtree.accel.Hit;
import org.kdtree.accel.Intersector;
import org.kdtree.generate.Shapes;
import org.kdtree.geom.Ray;
import org.kdtree.kdtree.KdTree;
import org.kdtree.shape.Scene2D;
import org.kdtree.spec.BuilderSpec;

/** The stepper's recording of the library's traversal: consistent steps, and the same hit as brute force. */
class TraversalRecorderTest {
    @Test void recordedTracesEndWithTheBruteForceHit() {
        Scene2D scene = new Scene2D(Shapes.clustered(300, 5).shapes());
        Random r = new Random(2);
        for (String b : CompareView.DEFAULT_BUILDERS) {
            KdTree tree = BuilderSpec.of(b).create().build(scene);
            BruteForce brute = new BruteForce(Intersector.of(scene));
            for (int i = 0; i < 200; i++) {
                double[] ray = {r.nextDouble() * 12 - 1, r.nextDouble() * 12 - 1, r.nextGaussian(), r.nextGaussian()};
                TraversalTrace t = TraversalRecorder.record(tree, scene, ray);
                Hit h = new Hit();
                boolean found = brute.closestHit(new Ray(2).set(ray[0], ray[1], ray[2], ray[3]), 0, Double.POSITIVE_INFINITY, h);
                assertThat(t.hitObject() >= 0).isEqualTo(found);
                if (found) assertThat(t.hitT()).isCloseTo(h.t, org.assertj.core.data.Offset.offset(1e-9));
                TraversalTrace.Step last = t.step(t.size() - 1);
                assertThat(last.kind()).isEqualTo(TraversalTrace.Kind.END);
                assertThat(last.bestObject()).isEqualTo(t.hitObject());
                long tests = t.steps().stream().filter(s -> s.kind() == TraversalTrace.Kind.TEST).count();
                assertThat(tests).isEqualTo(t.tests());
                long visits = t.steps().stream().filter(s -> s.kind() == TraversalTrace.Kind.INTERIOR || s.kind() == TraversalTrace.Kind.LEAF).count();
                assertThat(visits).isEqualTo(t.nodes());
            }
        }
    }

    @Test void theStackGrowsOnPushAndShrinksOnPop() {
        Scene2D scene = new Scene2D(Shapes.uniform(200, 3).shapes());
        KdTree tree = BuilderSpec.of("sah").create().build(scene);
        TraversalTrace t = TraversalRecorder.record(tree, scene, new double[] {-1, 0.3, 1, 0.02});
        int pushes = 0;
        for (int i = 1; i < t.size(); i++) {
            int before = t.step(i - 1).stack().size(), after = t.step(i).stack().size();
            switch (t.step(i).kind()) {
                case PUSH_FAR -> { assertThat(after).isEqualTo(before + 1); pushes++; }
                case POP, SKIP -> assertThat(after).isEqualTo(before - 1);
                default -> assertThat(after).isEqualTo(before);
            }
        }
        assertThat(pushes).as("a long ray across 200 objects visits both children somewhere").isPositive();
        assertThat(TraversalRecorder.record(tree, scene, null).size()).isZero();
    }

    @Test void aHierarchysTraceStepsThroughItsBoxesToTheBruteForceHit() {
        Scene2D scene = new Scene2D(Shapes.clustered(300, 5).shapes());
        org.kdtree.bvh.Bvh bvh = new org.kdtree.bvh.BvhBuilder().build(scene);
        BruteForce brute = new BruteForce(Intersector.of(scene));
        Random r = new Random(3);
        for (int i = 0; i < 200; i++) {
            double[] ray = {r.nextDouble() * 12 - 1, r.nextDouble() * 12 - 1, r.nextGaussian(), r.nextGaussian()};
            TraversalTrace t = TraversalRecorder.record(bvh, scene, ray);
            Hit h = new Hit();
            boolean found = brute.closestHit(new Ray(2).set(ray[0], ray[1], ray[2], ray[3]), 0, Double.POSITIVE_INFINITY, h);
            assertThat(t.hitObject() >= 0).isEqualTo(found);
            if (found) assertThat(t.hitT()).isCloseTo(h.t, org.assertj.core.data.Offset.offset(1e-9));
            assertThat(t.step(t.size() - 1).kind()).isEqualTo(TraversalTrace.Kind.END);
            assertThat(count(t, TraversalTrace.Kind.BOX_TEST)).isEqualTo(t.boxTests());
            assertThat(count(t, TraversalTrace.Kind.BOX_NODE) + count(t, TraversalTrace.Kind.LEAF)).isEqualTo(t.nodes());
            assertThat(count(t, TraversalTrace.Kind.INTERIOR)).as("no split planes in a hierarchy").isZero();
            for (TraversalTrace.Step s : t.steps()) {
                if (s.kind() == TraversalTrace.Kind.BOX_TEST)
                    assertThat(s.boxes()).as("a box test names a child of the node").last()
                            .matches(b -> b.node() == bvh.left(s.node()) || b.node() == bvh.right(s.node()));
                if (s.kind() == TraversalTrace.Kind.PUSH_FAR)
                    assertThat(s.near()).as("the nearer box entered, visited first").isNotNegative().isNotEqualTo(s.far());
            }
        }
    }

    private static long count(TraversalTrace t, TraversalTrace.Kind kind) {
        return t.steps().stream().filter(s -> s.kind() == kind).count();
    }
}
