package org.kdtree.gui;

import java.util.ArrayList;
import java.util.List;
import org.kdtree.collide.ShapeCollider;
import org.kdtree.geom.Box;
import org.kdtree.geom.Tolerance;
import org.kdtree.kdtree.KdTree;
import org.kdtree.shape.Scene2D;

/**
 * Searches the k objects of a 2-D scene nearest to a query point through the workbench's tree,
 * and records every event into a {@link NearestTrace} for the nearest-neighbour stepper.
 *
 * <p>The distance to an object is the exact distance to the object itself, not to its centre
 * ({@link ShapeCollider#closestPoint}: 0 inside a filled rectangle or triangle; a zero-area
 * rectangle or triangle is never a neighbour, as a ray never hits it). The search is the
 * library's point search ({@code points.NearestQuery}) carried over to objects: depth first,
 * near child first (the side of the split plane the query lies on), and a node is pruned when
 * the distance from the query to its voxel exceeds the k-th best distance found so far. An object
 * referenced by several leaves is tested once (mailbox). Nothing is lost by pruning: an object's
 * point nearest the query lies in some leaf that references it, and that leaf's voxel is no
 * farther than the point. Ties go to the lower object index, as a sort of all objects by
 * (distance, index) would order them.
 */
final class NearestRecorder {
    /** Relative slack on pruning, on squared distances ({@link Tolerance#PRUNE_SLACK}), as the point queries use. */
    static final double SLACK = Tolerance.PRUNE_SLACK;

    private final KdTree tree;
    private final ShapeCollider collider;
    private final double qx, qy;
    private final double[] q;
    private final int k;
    private final boolean[] tested;
    private final double[] lo = new double[2], hi = new double[2];
    private final double[] closest = new double[3];
    private final List<NearestTrace.Step> steps = new ArrayList<>();
    /** The k best so far, nearest first, with their squared distances alongside. */
    private final List<NearestTrace.Neighbour> best = new ArrayList<>();
    private final List<Double> bestSquared = new ArrayList<>();
    private List<NearestTrace.Neighbour> bestView = List.of();
    private long nodes, leaves, pruned, tests;

    private NearestRecorder(KdTree tree, Scene2D scene, double[] query, int k) {
        this.tree = tree;
        this.collider = new ShapeCollider(scene);
        this.qx = query[0];
        this.qy = query[1];
        this.q = new double[] {qx, qy};
        this.k = k;
        this.tested = new boolean[scene.size()];
        Box b = tree.bounds();
        for (int a = 0; a < 2; a++) {
            lo[a] = b.min(a);
            hi[a] = b.max(a);
        }
    }

    /**
     * Records the search for the {@code k} objects of {@code scene} nearest to {@code query}
     * {x, y} through {@code tree} (built over {@code scene}); the empty trace without a query.
     * @param tree the kd-tree over {@code scene}
     * @param scene the 2-D scene
     * @param query the query point {x, y}, or null
     * @param k the number of neighbours wanted
     * @return the recorded search
     */
    public static NearestTrace record(KdTree tree, Scene2D scene, double[] query, int k) {
        if (query == null) return NearestTrace.EMPTY;
        if (k < 1) throw new IllegalArgumentException("k must be >= 1, got " + k);
        if (!Double.isFinite(query[0]) || !Double.isFinite(query[1]))
            throw new IllegalArgumentException("the query point must be finite");
        NearestRecorder r = new NearestRecorder(tree, scene, query, k);
        r.add(NearestTrace.Kind.BEGIN, -1, Math.sqrt(r.voxelSquared()), -1, -1, -1, Double.NaN, false);
        if (tree.nodeCount() > 0) r.search(0);
        r.add(NearestTrace.Kind.END, -1, Double.NaN, -1, -1, -1, Double.NaN, false);
        return new NearestTrace(List.copyOf(r.steps), query.clone(), k, r.nodes, r.leaves, r.pruned, r.tests, r.bestView);
    }

    /** The squared distance from the query to the current voxel [lo, hi]. */
    private double voxelSquared() {
        double dx = Math.max(0, Math.max(lo[0] - qx, qx - hi[0]));
        double dy = Math.max(0, Math.max(lo[1] - qy, qy - hi[1]));
        return dx * dx + dy * dy;
    }

    /** The squared k-th best distance: +infinity while fewer than k objects are known. */
    private double kthSquared() {
        return best.size() < k ? Double.POSITIVE_INFINITY : bestSquared.get(k - 1);
    }

    /** Searches below {@code node}, whose voxel is the current [lo, hi]. */
    private void search(int node) {
        double vs = voxelSquared();
        if (vs > kthSquared() * (1 + SLACK)) {
            pruned++;
            add(NearestTrace.Kind.PRUNE, node, Math.sqrt(vs), -1, -1, -1, Double.NaN, false);
            return;
        }
        nodes++;
        if (tree.isLeaf(node)) {
            leaves++;
            add(NearestTrace.Kind.LEAF, node, Math.sqrt(vs), -1, -1, -1, Double.NaN, false);
            for (int i = tree.leafStart(node), end = tree.leafEnd(node); i < end; i++) test(node, tree.ref(i));
            return;
        }
        int axis = tree.axis(node);
        double split = tree.split(node);
        boolean rightIsNear = (axis == 0 ? qx : qy) > split;
        int near = rightIsNear ? tree.rightChild(node) : tree.leftChild(node);
        int far = rightIsNear ? tree.leftChild(node) : tree.rightChild(node);
        add(NearestTrace.Kind.INTERIOR, node, Math.sqrt(vs), near, far, -1, Double.NaN, false);
        double oldLo = lo[axis], oldHi = hi[axis];
        if (rightIsNear) lo[axis] = split; else hi[axis] = split;
        search(near);
        lo[axis] = oldLo;
        hi[axis] = oldHi;
        if (rightIsNear) hi[axis] = split; else lo[axis] = split;
        search(far);
        lo[axis] = oldLo;
        hi[axis] = oldHi;
    }

    private void test(int leaf, int object) {
        if (tested[object]) {
            add(NearestTrace.Kind.MAILBOXED, leaf, Double.NaN, -1, -1, object, Double.NaN, false);
            return;
        }
        tested[object] = true;
        tests++;
        closest[0] = closest[1] = Double.NaN;
        double ds = collider.closestPoint(object, q, closest);
        boolean improved = ds < Double.POSITIVE_INFINITY && offer(object, ds);
        double cx = closest[0], cy = closest[1];
        steps.add(new NearestTrace.Step(NearestTrace.Kind.TEST, leaf, Double.NaN, -1, -1, object, Math.sqrt(ds),
                ds < Double.POSITIVE_INFINITY ? cx : Double.NaN, ds < Double.POSITIVE_INFINITY ? cy : Double.NaN,
                improved, bestView, Math.sqrt(kthSquared())));
    }

    /** Keeps the object if it is among the k best so far, by (distance, index); says whether it was kept. */
    private boolean offer(int object, double ds) {
        int at = best.size();
        while (at > 0 && (bestSquared.get(at - 1) > ds || (bestSquared.get(at - 1) == ds && best.get(at - 1).object() > object)))
            at--;
        if (at >= k) return false;
        best.add(at, new NearestTrace.Neighbour(object, Math.sqrt(ds)));
        bestSquared.add(at, ds);
        if (best.size() > k) {
            best.remove(k);
            bestSquared.remove(k);
        }
        bestView = List.copyOf(best);
        return true;
    }

    private void add(NearestTrace.Kind kind, int node, double bound, int near, int far, int object, double distance,
                     boolean improved) {
        steps.add(new NearestTrace.Step(kind, node, bound, near, far, object, distance, Double.NaN, Double.NaN, improved,
                bestView, Math.sqrt(kthSquared())));
    }
}
