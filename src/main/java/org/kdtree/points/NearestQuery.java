package org.kdtree.points;

import org.kdtree.kdtree.Nodes;

/**
 * The k nearest neighbours of a query point, optionally within a maximum distance: exact by
 * default, approximate on request. One instance per thread (it owns its scratch memory: the
 * candidate heap, the voxel offsets, the put-aside branches) and reused across queries; a query
 * allocates nothing once the instance has seen its largest k (and, best-bin-first, its largest
 * number of put-aside branches). The {@link PointTree} is shared.
 *
 * <pre>
 * NearestQuery knn = new NearestQuery(points);
 * int[] nearest = new int[8];
 * double[] dist = new double[8];
 * int n = knn.nearest(q, 8, nearest, dist);    // nearest[0 .. n) nearest first
 * </pre>
 *
 * <p>Results are sorted by distance, ties by the lower point index: the same list a sort of all
 * points by (distance, index) gives. Distances are compared as the metric's accumulated
 * distances (squared, for Euclidean), and returned as true distances.
 *
 * <p>Exact search is depth first, near child first, with the far child pruned by its voxel's
 * distance ({@link VoxelDescent}). Two approximations, off by default, trade accuracy for time:
 * <ul>
 * <li>{@link #epsilon}: a voxel is skipped unless it is {@code (1 + eps)} times nearer than the
 * current k-th neighbour; each answer is then within {@code (1 + eps)} of the true k-th
 * distance (Arya and Mount).</li>
 * <li>{@link #maxLeaves}: best-bin-first (Beis and Lowe; FLANN's "checks"): the search always
 * continues from the nearest voxel put aside, and stops after scanning that many leaves.</li>
 * </ul>
 */
public final class NearestQuery extends VoxelDescent {
    /** A {@link #maxLeaves} that never stops the search early. */
    public static final int UNLIMITED = Integer.MAX_VALUE;

    private final NeighbourHeap heap = new NeighbourHeap();
    private BranchQueue branches;
    private double epsilon;
    private double reachScale = 1 + SLACK;
    private int maxLeaves = UNLIMITED;
    /** The largest accumulated distance a neighbour may have (slack included), +infinity without a maximum. */
    private double cap;

    /**
     * A query over {@code points}: exact, Euclidean, no leaf budget.
     *
     * @param points the points to search, shared with other queries
     */
    public NearestQuery(PointTree points) {
        super(points);
    }

    /**
     * Sets the metric (default {@link Metric#EUCLIDEAN}).
     *
     * @param m the metric
     * @return this query
     */
    public NearestQuery metric(Metric m) {
        setMetric(m);
        return epsilon(epsilon);
    }

    /** {@return the metric distances are measured in} */
    public Metric metric() { return metric; }

    /**
     * Sets eps >= 0 (default 0, exact): prune a voxel unless its distance times {@code 1 + eps}
     * is within the current k-th distance. Every neighbour returned is then within
     * {@code (1 + eps)} times the distance of the true neighbour of its rank.
     *
     * @param eps the allowed relative error, finite and >= 0
     * @return this query
     * @throws IllegalArgumentException if {@code eps} is negative, infinite or NaN
     */
    public NearestQuery epsilon(double eps) {
        if (!(eps >= 0 && eps < Double.POSITIVE_INFINITY)) throw new IllegalArgumentException("epsilon must be finite and >= 0, got " + eps);
        this.epsilon = eps;
        this.reachScale = (1 + SLACK) / metric.accumulated(1 + eps);
        return this;
    }

    /** {@return eps, the allowed relative error (0: exact)} */
    public double epsilon() { return epsilon; }

    /**
     * Sets the budget of leaves (>= 1, or {@link #UNLIMITED}, the default): with a budget, the
     * search is best-bin-first and stops once it has scanned that many leaves; a budget at least
     * the tree's leaf count gives the exact answer.
     *
     * @param leaves the most leaves a query scans, >= 1, or {@link #UNLIMITED}
     * @return this query
     * @throws IllegalArgumentException if {@code leaves < 1}
     */
    public NearestQuery maxLeaves(int leaves) {
        if (leaves < 1) throw new IllegalArgumentException("max leaves must be >= 1, got " + leaves);
        this.maxLeaves = leaves;
        return this;
    }

    /** {@return the budget of leaves per query, {@link #UNLIMITED} for none} */
    public int maxLeaves() { return maxLeaves; }

    /** {@return the leaves scanned by the last query (a measure of its work)} */
    public int leavesVisited() { return leavesVisited; }

    /**
     * The {@code k} points nearest to {@code query} (fewer if there are fewer points), nearest
     * first, into {@code indices} and, unless null, their distances into {@code distances}; both
     * must hold {@code min(k, number of points)} values. Returns how many were written.
     *
     * @param query     the query point, one coordinate per dimension
     * @param k         how many neighbours to find, >= 1
     * @param indices   receives the neighbours' point indices, nearest first
     * @param distances receives their true distances, or null
     * @return the number of neighbours written, {@code min(k, number of points)}
     * @throws IllegalArgumentException if {@code k < 1} or an array is too short
     */
    public int nearest(double[] query, int k, int[] indices, double[] distances) {
        return nearest(query, k, Double.POSITIVE_INFINITY, indices, distances);
    }

    /**
     * As {@link #nearest(double[], int, int[], double[])}, keeping only the points at distance
     * {@code <= maxDistance} (>= 0; infinity for no limit), so possibly fewer than k.
     *
     * @param query       the query point, one coordinate per dimension
     * @param k           how many neighbours to find at most, >= 1
     * @param maxDistance the largest distance a neighbour may have, >= 0 (infinity for no limit)
     * @param indices     receives the neighbours' point indices, nearest first
     * @param distances   receives their true distances, or null
     * @return the number of neighbours written, at most {@code min(k, number of points)}
     * @throws IllegalArgumentException if {@code k < 1}, {@code maxDistance} is negative or NaN,
     *                                  or an array is too short
     */
    public int nearest(double[] query, int k, double maxDistance, int[] indices, double[] distances) {
        if (k < 1) throw new IllegalArgumentException("k must be >= 1, got " + k);
        if (!(maxDistance >= 0)) throw new IllegalArgumentException("max distance must be >= 0, got " + maxDistance);
        int most = Math.min(k, points.size());
        if (indices.length < most || (distances != null && distances.length < most))
            throw new IllegalArgumentException("the result arrays must hold min(k, points) = " + most + " values");
        double rd = begin(query);
        heap.reset(k);
        cap = metric.accumulated(maxDistance) * (1 + SLACK);
        if (points.size() > 0) {
            if (maxLeaves == UNLIMITED) descend(0, rd);
            else bestBinFirst(rd);
        }
        return heap.drainSorted(metric, maxDistance, indices, distances);
    }

    /** The accumulated distance a point must beat (or tie with a lower index) to be kept. */
    private double bound() {
        return Math.min(heap.worst(), cap);
    }

    @Override double reach() {
        return bound() * reachScale;
    }

    @Override void scanLeaf(int from, int to) {
        for (int j = from; j < to; j++) {
            double bound = bound();
            double acc = metric.accumulated(q, coords, j * k, bound);
            if (acc <= bound) heap.offer(acc, refs[j]);
        }
    }

    /**
     * Best-bin-first: walk from the nearest branch put aside down to a leaf, putting aside each
     * far child on the way, scan the leaf; repeat until the budget is spent or the nearest
     * branch left is out of reach (then the answer is exact).
     */
    private void bestBinFirst(double rootDistance) {
        if (branches == null) branches = new BranchQueue(k);
        branches.clear();
        branches.push(0, rootDistance, off);
        while (!branches.isEmpty() && leavesVisited < maxLeaves) {
            double rd = branches.nearestDistance();
            if (rd > reach()) break; // the nearest branch is out of reach, and so are the others
            int node = branches.popNearest(off);
            int w = Nodes.word(nodes, node);
            while (!Nodes.isLeaf(w, bits)) {
                int axis = Nodes.axis(w, bits);
                double diff = q[axis] - Nodes.split(nodes, node);
                int near = Nodes.leftChild(node), far = Nodes.rightChild(w, bits);
                if (diff > 0) { near = far; far = Nodes.leftChild(node); }
                double old = off[axis];
                double farRd = metric.replace(rd, old, diff);
                if (farRd <= reach()) {
                    off[axis] = Math.abs(diff);
                    branches.push(far, farRd, off);
                    off[axis] = old;
                }
                node = near;
                w = Nodes.word(nodes, node);
            }
            scan(node, w);
        }
    }
}
