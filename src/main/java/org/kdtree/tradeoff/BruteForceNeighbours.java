package org.kdtree.tradeoff;

import org.kdtree.shape.PointsKd;

/**
 * The k nearest neighbours by scanning every point (Euclidean): the oracle a study checks
 * approximate answers against, and the baseline it times the tree against. Each query keeps
 * the distances of its best k in a sorted array and gives up a point as soon as its partial sum
 * of squares passes the current k-th, as the tree's leaf scan does, so that the comparison is
 * fair. Squared distances are summed axis 0 first, as {@code Metric.EUCLIDEAN} sums them, so
 * the two agree to the last bit. One instance per thread.
 */
final class BruteForceNeighbours {
    private final double[] coords;
    private final int n;
    private final int dim;
    private double[] best = new double[0];

    /** @param points at least one point */
    public BruteForceNeighbours(PointsKd points) {
        if (points.size() == 0) throw new IllegalArgumentException("no points to search");
        this.coords = flat(points);
        this.n = points.size();
        this.dim = points.dimension();
    }

    /** The points' coordinates in one array, point after point. */
    static double[] flat(PointsKd points) {
        int k = points.dimension();
        double[] c = new double[points.size() * k];
        for (int i = 0; i < points.size(); i++) for (int a = 0; a < k; a++) c[i * k + a] = points.coord(i, a);
        return c;
    }

    /**
     * Scans for the {@code min(k, points)} nearest points to {@code query} and returns the
     * squared distance of the farthest of them, the k-th: every point at most that far is a
     * correct neighbour (so that of two points at the same distance either will do).
     *
     * @param query the query point, one coordinate per dimension
     * @param k     how many neighbours, >= 1 (fewer if there are fewer points)
     * @return the squared Euclidean distance of the {@code min(k, points)}-th nearest point
     */
    public double kthSquaredDistance(double[] query, int k) {
        int kk = Math.min(k, n);
        if (best.length < kk) best = new double[kk];
        int held = 0;
        for (int i = 0; i < n; i++) {
            double bound = held < kk ? Double.POSITIVE_INFINITY : best[kk - 1];
            double d = squaredDistance(query, i, bound);
            if (d < bound) held = insert(d, held, kk);
        }
        return best[kk - 1];
    }

    /** The squared distance from {@code query} to point {@code i}, axis 0 first (stops early past {@code bound}). */
    double squaredDistance(double[] query, int i, double bound) {
        double sum = 0;
        int p = i * dim;
        for (int a = 0; a < dim; a++) {
            double diff = query[a] - coords[p + a];
            sum += diff * diff;
            if (sum > bound) return sum;
        }
        return sum;
    }

    /** Puts a distance into the sorted best list, dropping the k-th if it is full; returns how many it holds. */
    private int insert(double d, int held, int kk) {
        int j = Math.min(held, kk - 1);
        while (j > 0 && best[j - 1] > d) {
            best[j] = best[j - 1];
            j--;
        }
        best[j] = d;
        return Math.min(held + 1, kk);
    }
}
