package org.kdtree.points;

import org.kdtree.geom.Tolerance;
import org.kdtree.kdtree.KdTree;
import org.kdtree.kdtree.Nodes;

/**
 * The exact search shared by the nearest-neighbour and the radius query: descend the near child
 * first, then visit the far child only if its voxel is within reach of the query.
 *
 * <p>The distance from the query to a voxel is kept incrementally (Arya and Mount): {@link #off}
 * holds, per axis, how far the query lies outside the current voxel (0 inside), and the voxel's
 * accumulated distance is the metric's sum of those. Crossing a split plane into the far child
 * changes one axis only, from its old offset to the distance to the plane, so the far voxel's
 * distance costs one {@link Metric#replace}, not a pass over k axes, and it is the distance to the
 * whole voxel, a tighter bound than the distance to the plane alone.
 *
 * <p>One instance per thread: the offsets and the query live in fields; nothing is allocated.
 */
abstract class VoxelDescent {
    /** Relative slack on pruning ({@link Tolerance#PRUNE_SLACK}): ties at the bound are never lost to an ulp. */
    static final double SLACK = Tolerance.PRUNE_SLACK;

    final PointTree points;
    final int k;
    /** The tree's nodes ({@link KdTree#nodeArray()}), read with {@link Nodes}. */
    final int[] nodes;
    /** The tree's {@link KdTree#axisBits()}, which {@link Nodes} decodes a word with. */
    final int bits;
    final double[] coords;
    final int[] refs;
    private final double[] rootMin, rootMax;
    /** Per axis, how far the query lies outside the current voxel. */
    final double[] off;
    Metric metric = Metric.EUCLIDEAN;
    /** The current query point (the caller's array, not copied). */
    double[] q;
    int leavesVisited;

    VoxelDescent(PointTree points) {
        this.points = points;
        KdTree tree = points.tree();
        k = points.dimension();
        nodes = tree.nodeArray();
        bits = tree.axisBits();
        refs = tree.refArray();
        coords = points.leafCoordArray();
        rootMin = new double[k];
        rootMax = new double[k];
        var b = tree.bounds();
        for (int a = 0; a < k; a++) {
            rootMin[a] = b.min(a);
            rootMax[a] = b.max(a);
        }
        off = new double[k];
    }

    /** Sets the metric (default Euclidean). */
    void setMetric(Metric m) {
        this.metric = java.util.Objects.requireNonNull(m);
    }

    /** Starts a query at {@code query}: checks it, sets the offsets to the root voxel, returns its accumulated distance. */
    final double begin(double[] query) {
        if (query.length != k) throw new IllegalArgumentException("query is " + query.length + "-D, points " + k + "-D");
        double acc = 0;
        for (int a = 0; a < k; a++) {
            if (!Double.isFinite(query[a])) throw new IllegalArgumentException("query coordinate " + a + " is not finite: " + query[a]);
            off[a] = Math.max(0, Math.max(rootMin[a] - query[a], query[a] - rootMax[a]));
            acc = metric.replace(acc, 0, off[a]);
        }
        q = query;
        leavesVisited = 0;
        return acc;
    }

    /** The bound a voxel's accumulated distance must not exceed for it to be visited. */
    abstract double reach();

    /** Examines the points at positions {@code [from, to)} of the leaf order. */
    abstract void scanLeaf(int from, int to);

    /** The exact depth-first search below {@code node}, whose voxel lies at accumulated distance {@code rd}. */
    final void descend(int node, double rd) {
        int w = Nodes.word(nodes, node);
        if (Nodes.isLeaf(w, bits)) {
            scan(node, w);
            return;
        }
        int axis = Nodes.axis(w, bits);
        double diff = q[axis] - Nodes.split(nodes, node);
        int near = Nodes.leftChild(node), far = Nodes.rightChild(w, bits);
        if (diff > 0) { near = far; far = Nodes.leftChild(node); }
        descend(near, rd);
        double old = off[axis];
        double farRd = metric.replace(rd, old, diff);
        if (farRd <= reach()) {
            off[axis] = Math.abs(diff);
            descend(far, farRd);
            off[axis] = old;
        }
    }

    /** Scans leaf {@code node}, whose word is {@code w}. */
    final void scan(int node, int w) {
        leavesVisited++;
        int first = Nodes.leafStart(nodes, node);
        scanLeaf(first, first + Nodes.leafSize(w, bits));
    }
}
