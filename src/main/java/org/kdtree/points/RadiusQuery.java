package org.kdtree.points;

/**
 * All points within a distance of a query point, nearest first (ties by lower index). One
 * instance per thread, reused across queries; it collects matches in arrays of its own, which
 * grow only when a query finds more points than any before it. The {@link PointTree} is shared.
 *
 * <p>The search is {@link VoxelDescent}'s exact one with a fixed reach: a voxel is visited when
 * its distance is within the radius.
 */
public final class RadiusQuery extends VoxelDescent {
    private double[] found = new double[64];
    private int[] foundIndex = new int[64];
    private int count;
    private double reach;

    /**
     * A query over {@code points}, Euclidean.
     *
     * @param points the points to search, shared with other queries
     */
    public RadiusQuery(PointTree points) {
        super(points);
    }

    /**
     * Sets the metric (default {@link Metric#EUCLIDEAN}).
     *
     * @param m the metric
     * @return this query
     */
    public RadiusQuery metric(Metric m) {
        setMetric(m);
        return this;
    }

    /** {@return the metric distances are measured in} */
    public Metric metric() { return metric; }

    /** {@return the leaves scanned by the last query} */
    public int leavesVisited() { return leavesVisited; }

    /**
     * The points at distance {@code <= radius} (>= 0) from {@code query}, nearest first: the
     * first {@code min(count, indices.length)} go into {@code indices} and, unless null, their
     * distances into {@code distances} (at least as long as {@code indices}). Returns the count
     * of all such points, which may exceed what the arrays hold: call again with larger ones.
     *
     * @param query     the query point, one coordinate per dimension
     * @param radius    the largest distance a match may have, finite and >= 0
     * @param indices   receives the matches' point indices, nearest first
     * @param distances receives their true distances, or null
     * @return the number of points within {@code radius}, whether or not they all fit
     * @throws IllegalArgumentException if {@code radius} is negative, infinite or NaN, or
     *                                  {@code distances} is shorter than {@code indices}
     */
    public int within(double[] query, double radius, int[] indices, double[] distances) {
        if (!(radius >= 0 && radius < Double.POSITIVE_INFINITY)) throw new IllegalArgumentException("radius must be finite and >= 0, got " + radius);
        if (distances != null && distances.length < indices.length)
            throw new IllegalArgumentException("distances must be at least as long as indices");
        double rd = begin(query);
        count = 0;
        reach = metric.accumulated(radius) * (1 + SLACK);
        if (points.size() > 0 && rd <= reach) descend(0, rd);
        PairSort.sort(found, foundIndex, count);
        int n = 0;
        for (int i = 0; i < count; i++) {
            double d = metric.distance(found[i]);
            if (d > radius) break; // the reach's slack let it in; its true distance is outside
            if (n < indices.length) {
                indices[n] = foundIndex[i];
                if (distances != null) distances[n] = d;
            }
            n++;
        }
        return n;
    }

    @Override double reach() { return reach; }

    @Override void scanLeaf(int from, int to) {
        for (int j = from; j < to; j++) {
            double acc = metric.accumulated(q, coords, j * k, reach);
            if (acc <= reach) add(acc, refs[j]);
        }
    }

    private void add(double acc, int point) {
        if (count == found.length) {
            found = java.util.Arrays.copyOf(found, 2 * count);
            foundIndex = java.util.Arrays.copyOf(foundIndex, 2 * count);
        }
        found[count] = acc;
        foundIndex[count++] = point;
    }
}
