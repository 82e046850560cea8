package org.kdtree.kdtree;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.kdtree.accel.Hit;
import org.kdtree.accel.TraversalListener;
import org.kdtree.accel.TraversalStats;
import org.kdtree.accel.TriangleIntersector;
import org.kdtree.generate.Meshes;
import org.kdtree.geom.Ray;
import org.kdtree.shape.TriangleMesh;
import org.kdtree.spec.Builders;

/** allHits, anyHit, statistics, mailboxing and the listener's event stream. */
class QueriesTest {
    private final TriangleMesh mesh = new MeshBuilder().mesh(Meshes.uniform(400, 0.3, 3)).mesh(Scenes.gridCube(4, 0.25)).build();
    private final TriangleIntersector tris = new TriangleIntersector(mesh);

    @Test void allHitsAreBruteForceHitsInOrderEachPrimitiveOnce() {
        Random rnd = new Random(4);
        Ray ray = new Ray(3);
        int total = 0;
        for (String b : Builders.names()) {
            Traverser t = new Traverser(Builders.create(b).build(mesh));
            for (int i = 0; i < 300; i++) {
                ray.set(rnd.nextDouble(), rnd.nextDouble(), rnd.nextDouble(), rnd.nextGaussian(), rnd.nextGaussian(),
                        rnd.nextGaussian());
                List<Hit> got = t.allHits(ray, 0, Double.POSITIVE_INFINITY);
                List<Integer> want = new ArrayList<>();
                for (int p = 0; p < tris.size(); p++) if (tris.intersect(p, ray, 0, Double.POSITIVE_INFINITY, new Hit())) want.add(p);
                assertThat(got).extracting(h -> h.primitive).containsExactlyInAnyOrderElementsOf(want);
                for (int k = 1; k < got.size(); k++) assertThat(got.get(k).t).isGreaterThanOrEqualTo(got.get(k - 1).t);
                total += got.size();
            }
        }
        assertThat(total).isGreaterThan(1000);
    }

    @Test void statisticsCountAndMailboxingTestsEachPrimitiveOncePerRay() {
        Traverser t = new Traverser(Builders.create("sah").build(mesh));
        Random rnd = new Random(5);
        Ray ray = new Ray(3);
        for (int i = 0; i < 200; i++) {
            ray.set(rnd.nextDouble(), rnd.nextDouble(), rnd.nextDouble(), rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian());
            List<Integer> tested = new ArrayList<>();
            TraversalStats stats = new TraversalStats();
            TraversalListener both = new TraversalListener() {
                @Override public void primitive(int p, boolean hit, double tt) { tested.add(p); stats.primitive(p, hit, tt); }
                @Override public void leaf(int n, double a, double b, int c) { stats.leaf(n, a, b, c); }
                @Override public void interior(int n, int ax, double s, double a, double b, double ts, int ne, int fa, Visit v) {
                    stats.interior(n, ax, s, a, b, ts, ne, fa, v);
                }
            };
            t.allHits(ray, 0, Double.POSITIVE_INFINITY, both);
            assertThat(tested).doesNotHaveDuplicates();
            assertThat(stats.nodes).isGreaterThanOrEqualTo(stats.leaves);
            assertThat(stats.primitiveTests).isEqualTo(tested.size());
        }
    }

    @Test void listenerReplaysAConsistentTraversal() {
        Traverser t = new Traverser(Builders.create("sah").build(mesh));
        Ray ray = new Ray(3).set(-0.5, 0.4, 0.3, 1, 0.1, 0.05);
        List<String> events = new ArrayList<>();
        int[] depth = {0};
        Hit hit = new Hit();
        boolean found = t.closestHit(ray, 0, Double.POSITIVE_INFINITY, hit, new TraversalListener() {
            @Override public void begin(double a, double b) { events.add("begin"); }
            @Override public void pushFar(int n, double a, double b) { depth[0]++; events.add("push"); }
            @Override public void pop(int n, double a, double b, boolean s) { depth[0]--; events.add("pop"); }
            @Override public void leaf(int n, double a, double b, int c) { events.add("leaf"); }
            @Override public void end(boolean f, Hit h) { events.add("end " + f + " " + h.primitive); }
        });
        assertThat(found).isTrue();
        assertThat(events.get(0)).isEqualTo("begin");
        assertThat(events.get(events.size() - 1)).isEqualTo("end true " + hit.primitive);
        assertThat(events).contains("leaf");
        assertThat(depth[0]).as("pushes minus pops: far children never visited").isGreaterThanOrEqualTo(0);
    }

    @Test void anyHitStopsEarlyAndRespectsTheRange() {
        Traverser t = new Traverser(Builders.create("sah").build(mesh));
        Ray ray = new Ray(3).set(-1, 0.5, 0.5, 1, 0, 0);
        Hit closest = new Hit();
        assertThat(t.closestHit(ray, 0, Double.POSITIVE_INFINITY, closest)).isTrue();
        assertThat(t.anyHit(ray, 0, closest.t)).isTrue();
        assertThat(t.anyHit(ray, 0, Math.nextDown(closest.t))).isFalse();
        TraversalStats all = new TraversalStats(), any = new TraversalStats();
        t.allHits(ray, 0, Double.POSITIVE_INFINITY, all);
        t.anyHit(ray, 0, Double.POSITIVE_INFINITY, any);
        assertThat(any.primitiveTests).isLessThanOrEqualTo(all.primitiveTests);
        assertThat(any.hits).isEqualTo(1);
    }

    @Test void invalidRaysAreRejectedClearly() {
        Traverser t = new Traverser(Builders.create("sah").build(mesh));
        assertThatThrownBy(() -> t.closestHit(new Ray(3).set(0, 0, 0, 0, 0, 0), 0, 1, new Hit()))
                .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("zero");
        assertThatThrownBy(() -> t.anyHit(new Ray(3).set(Double.NaN, 0, 0, 1, 0, 0), 0, 1))
                .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("non-finite");
        assertThat(t.closestHit(new Ray(3).set(0, 0, 0, 1, 0, 0), 2, 1, new Hit())).as("empty range").isFalse();
    }

    @Test void emptySceneMissesEverything() {
        TriangleMesh none = new TriangleMesh(new double[0], new int[0]);
        Traverser t = new Traverser(Builders.create("sah").build(none));
        assertThat(t.closestHit(new Ray(3).set(0, 0, 0, 1, 0, 0), 0, Double.POSITIVE_INFINITY, new Hit())).isFalse();
        assertThat(t.anyHit(new Ray(3).set(0, 0, 0, 1, 0, 0), 0, Double.POSITIVE_INFINITY)).isFalse();
    }
}
