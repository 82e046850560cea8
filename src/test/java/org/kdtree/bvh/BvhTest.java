package org.kdtree.bvh;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.Arrays;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.kdtree.accel.BruteForce;
import org.kdtree.accel.Hit;
import org.kdtree.accel.Intersector;
import org.kdtree.accel.RayQuery;
import org.kdtree.accel.TraversalStats;
import org.kdtree.accel.TreeStats;
import org.kdtree.accel.TriangleIntersector;
import org.kdtree.generate.Meshes;
import org.kdtree.generate.Shapes;
import org.kdtree.geom.Box;
import org.kdtree.geom.Ray;
import org.kdtree.shape.Primitives;
import org.kdtree.shape.Scene2D;
import org.kdtree.shape.TriangleMesh;

/**
 * The hierarchy's invariants (each primitive in exactly one leaf, boxes that bound what they
 * hold, leaves within their size, depth within its cap, the same hierarchy on any thread count)
 * and its queries against brute force, in 3-D and 2-D, on both layouts. The hard cases are
 * {@code traverse.HardCases3DTest} and {@code HardCases2DTest}, which take the BVH among the builders.
 */
@Timeout(120)   // a layout with a cycle would trace forever: fail instead
class BvhTest {
    private static final double EPS = 1e-9;

    @Test void everyPrimitiveIsInExactlyOneLeafWhoseBoxesBoundIt() {
        for (Primitives p : new Primitives[] {Meshes.uniform(3000, 1), Meshes.clustered(3000, 2), Meshes.flat(500, 3),
                Meshes.planarAndDegenerate(4), Shapes.mixed(400, 5)}) {
            Bvh h = new BvhBuilder().build(p);
            int[] seen = new int[p.size()];
            checkNode(h, p, 0, seen, h.nodeBounds(0));
            Box b = new Box(p.dimension());
            for (int i = 0; i < p.size(); i++) {
                p.bounds(i, b);
                assertThat(seen[i]).as("primitive " + i).isEqualTo(b.isEmpty() ? 0 : 1);
            }
            TreeStats st = h.stats();
            assertThat(st.references()).isEqualTo(h.primitiveCount());
            assertThat(st.nodes()).isEqualTo(2 * st.leaves() - 1);
        }
    }

    /** Walks the binary tree: every node's box lies within its parent's, every leaf's primitives within its box. */
    private static void checkNode(Bvh h, Primitives p, int node, int[] seen, Box parent) {
        Box box = h.nodeBounds(node);
        for (int a = 0; a < p.dimension(); a++)
            assertThat(box.min(a) >= parent.min(a) && box.max(a) <= parent.max(a)).as("node " + node + " in its parent").isTrue();
        if (!h.isLeaf(node)) {
            checkNode(h, p, h.left(node), seen, box);
            checkNode(h, p, h.right(node), seen, box);
            return;
        }
        assertThat(h.leafSize(node)).isLessThanOrEqualTo(16);
        Box b = new Box(p.dimension());
        for (int r = h.leafStart(node); r < h.leafStart(node) + h.leafSize(node); r++) {
            int prim = h.primitive(r);
            seen[prim]++;
            p.bounds(prim, b);
            for (int a = 0; a < p.dimension(); a++)
                assertThat(b.min(a) >= box.min(a) && b.max(a) <= box.max(a)).as("primitive " + prim + " in leaf " + node).isTrue();
        }
    }

    @Test void theWideLayoutReachesEveryNodeOnceAndEveryPrimitiveOnceAtEveryWidth() {
        // Uniform triangles make wide nodes with few children: more nodes than the layout first makes room for.
        for (TriangleMesh m : new TriangleMesh[] {Meshes.surface(20_000, 3), Meshes.uniform(2000, 4)})
        for (int width = 2; width <= 8; width++) {
            Bvh h = new BvhBuilder().width(width).build(m);
            WideNodes w = new WideNodes(h, width);   // every width, whichever the JVM traces
            int[] seenNode = new int[w.nodeCount()], seenRef = new int[h.primitiveCount()];
            java.util.ArrayDeque<Integer> todo = new java.util.ArrayDeque<>(java.util.List.of(0));
            int visits = 0;
            while (!todo.isEmpty()) {
                int node = todo.pop();
                assertThat(++visits).as("width " + width + ": a cycle").isLessThanOrEqualTo(w.nodeCount());
                seenNode[node]++;
                for (int i = 0; i < width; i++) {
                    int ref = w.words[w.stride * node + w.refs + i], count = w.words[w.stride * node + w.refs + width + i];
                    if (count == 0) todo.push(ref);
                    for (int r = ref; r < ref + Math.max(0, count); r++) seenRef[r]++;
                }
            }
            assertThat(seenNode).as("width " + width).containsOnly(1);
            assertThat(seenRef).as("width " + width).containsOnly(1);
        }
    }

    @Test void theSameHierarchyOnAnyThreadCount() {
        TriangleMesh m = Meshes.clustered(40_000, 7);
        Bvh one = new BvhBuilder().build(m), four = new BvhBuilder().threads(4).build(m);
        assertThat(four.nodeCount()).isEqualTo(one.nodeCount());
        assertThat(Arrays.equals(four.primitiveArray(), one.primitiveArray())).isTrue();
        assertThat(Arrays.equals(four.boxArray(), one.boxArray())).isTrue();
        assertThat(Arrays.equals(four.linkArray(), one.linkArray())).isTrue();
        assertThat(four.stats()).isEqualTo(one.stats());
    }

    @Test void anInterruptedBuildStopsWithCancellation() {
        Thread.currentThread().interrupt();
        try {
            assertThatThrownBy(() -> new BvhBuilder().build(Meshes.clustered(5000, 3)))
                    .isInstanceOf(java.util.concurrent.CancellationException.class).hasMessage("BVH build interrupted");
        } finally {
            Thread.interrupted();
        }
    }

    @Test void theDepthCapHoldsOnAnyDistributionAndLeavesStayWithinTheirSize() {
        TriangleMesh m = chain(2000);
        for (int cap : new int[] {-1, 12, 3}) {
            Bvh h = new BvhBuilder().maxDepth(cap).build(m);
            assertThat(h.maxDepth()).isLessThanOrEqualTo(cap < 0 ? BvhBuilder.DEPTH_LIMIT : cap);
            if (cap != 3) for (int node = 0; node < h.nodeCount(); node++)
                if (h.isLeaf(node)) assertThat(h.leafSize(node)).as("cap " + cap).isLessThanOrEqualTo(16);
            agreesWithBruteForce(m, new TriangleIntersector(m), h, 300, 11);
        }
    }

    /** Centroids at 2^-i: every binned plane cuts off only the farthest few, a chain without the cap's guard. */
    static TriangleMesh chain(int n) {
        double[] v = new double[9 * n];
        int[] idx = new int[3 * n];
        for (int i = 0; i < n; i++) {
            double x = Math.pow(2, -i / 20.0);
            System.arraycopy(new double[] {x, 0, 0, x * 1.001, 1, 0, x, 0, 1}, 0, v, 9 * i, 9);
            for (int c = 0; c < 3; c++) idx[3 * i + c] = 3 * i + c;
        }
        return new TriangleMesh(v, idx);
    }

    @Test void closestAndAnyHitAgreeWithBruteForceInBothLayoutsAndEveryWidth() {
        TriangleMesh m = Meshes.clustered(2000, 9);
        TriangleIntersector x = new TriangleIntersector(m);
        for (int width = 2; width <= 8; width++)
            agreesWithBruteForce(m, x, new BvhBuilder().width(width).leafSize(4).build(m), 400, width);
        Scene2D s = Shapes.mixed(300, 12);
        agreesWithBruteForce(s, Intersector.of(s), new BvhBuilder().build(s), 800, 13);
    }

    @Test void anEmptySceneIsMissedAndStatisticsCountTheBoxesTested() {
        TriangleMesh empty = new TriangleMesh(new double[0], new int[0]);
        Bvh h = new BvhBuilder().build(empty);
        Ray ray = new Ray(3).set(0, 0, 0, 1, 0, 0);
        assertThat(h.query().closestHit(ray, 0, Double.POSITIVE_INFINITY, new Hit())).isFalse();
        TriangleMesh m = Meshes.uniform(500, 3);
        TraversalStats stats = new TraversalStats();
        RayQuery q = new BvhBuilder().build(m).query(stats);
        Box b = m.bounds();
        ray.set(b.min(0) - 1, (b.min(1) + b.max(1)) / 2, (b.min(2) + b.max(2)) / 2, 1, 0, 0);
        q.closestHit(ray, 0, Double.POSITIVE_INFINITY, new Hit());
        assertThat(stats.rays).isEqualTo(1);
        assertThat(stats.boxTests).isGreaterThanOrEqualTo(2);
        assertThat(stats.primitiveTests).isPositive();
    }

    /** Random rays from around and inside the scene, each closest hit and any hit against brute force. */
    static void agreesWithBruteForce(Primitives p, Intersector x, Bvh h, int rays, long seed) {
        BruteForce brute = new BruteForce(x);
        RayQuery fast = h.query(), listened = h.query(new TraversalStats());
        Box b = p.bounds();
        int k = p.dimension();
        Random r = new Random(seed);
        Ray ray = new Ray(k);
        Hit want = new Hit(), got = new Hit();
        double[] o = new double[k], d = new double[k];
        for (int i = 0; i < rays; i++) {
            for (int a = 0; a < k; a++) {
                double ext = b.max(a) - b.min(a);
                o[a] = b.min(a) - 0.2 * ext + 1.4 * ext * r.nextDouble();
                d[a] = r.nextGaussian();
            }
            ray.set(o, d);
            boolean w = brute.closestHit(ray, 0, Double.POSITIVE_INFINITY, want);
            for (RayQuery q : new RayQuery[] {fast, listened}) {
                boolean g = q.closestHit(ray, 0, Double.POSITIVE_INFINITY, got);
                assertThat(g).as("ray " + i + " " + ray).isEqualTo(w);
                if (w) assertThat(Math.abs(got.t - want.t)).as("ray " + i).isLessThanOrEqualTo(EPS * Math.max(1, want.t));
                assertThat(q.anyHit(ray, 0, Double.POSITIVE_INFINITY)).isEqualTo(w);
            }
        }
    }
}
