package org.kdtree.points;

/**
 * A Minkowski distance {@code (sum |x_a - y_a|^p)^(1/p)}, p >= 1, or its limit p = infinity, the
 * largest coordinate difference. Euclidean (p = 2) is the default of every query.
 *
 * <p>The queries never take the p-th root while they search: they compare <em>accumulated</em>
 * distances, {@code sum |d_a|^p} (for p = infinity, {@code max |d_a|}), which grow monotonically
 * axis by axis, so a point can be given up as soon as its partial sum passes the bound, and a
 * voxel's distance can be updated one axis at a time. Only results are turned into true
 * distances ({@link #distance}).
 */
public final class Metric {
    private static final int EUCLIDEAN_KIND = 0, MANHATTAN_KIND = 1, CHEBYSHEV_KIND = 2, GENERAL_KIND = 3;

    /** p = 2, the default. */
    public static final Metric EUCLIDEAN = new Metric(2);
    /** p = 1, the sum of the coordinate differences. */
    public static final Metric MANHATTAN = new Metric(1);
    /** p = infinity, the largest coordinate difference. */
    public static final Metric CHEBYSHEV = new Metric(Double.POSITIVE_INFINITY);

    private final double p;
    private final int kind;

    private Metric(double p) {
        this.p = p;
        this.kind = p == 2 ? EUCLIDEAN_KIND : p == 1 ? MANHATTAN_KIND : p == Double.POSITIVE_INFINITY ? CHEBYSHEV_KIND : GENERAL_KIND;
    }

    /**
     * The Minkowski metric of order {@code p}: p >= 1 (below 1 it is no metric), or positive infinity.
     *
     * @param p the order, >= 1 or {@link Double#POSITIVE_INFINITY}
     * @return the metric; one of the constants for p = 1, 2 or infinity
     * @throws IllegalArgumentException if {@code p} is below 1 or NaN
     */
    public static Metric minkowski(double p) {
        if (!(p >= 1)) throw new IllegalArgumentException("a Minkowski metric needs p >= 1 (or infinity), got " + p);
        return p == 2 ? EUCLIDEAN : p == 1 ? MANHATTAN : p == Double.POSITIVE_INFINITY ? CHEBYSHEV : new Metric(p);
    }

    /** {@return p, the order} */
    public double p() { return p; }

    /** The contribution of one axis whose coordinates differ by {@code diff}. */
    double term(double diff) {
        return switch (kind) {
            case EUCLIDEAN_KIND -> diff * diff;
            case MANHATTAN_KIND, CHEBYSHEV_KIND -> Math.abs(diff);
            default -> Math.pow(Math.abs(diff), p);
        };
    }

    /**
     * The accumulated distance after one axis's difference changes from {@code oldDiff} to
     * {@code newDiff}, where {@code |newDiff| >= |oldDiff|}: the incremental voxel distance of
     * Arya and Mount, exact for a sum, and for the maximum because the axis's share only grows.
     */
    double replace(double acc, double oldDiff, double newDiff) {
        if (kind == CHEBYSHEV_KIND) return Math.max(acc, Math.abs(newDiff));
        return acc - term(oldDiff) + term(newDiff);
    }

    /**
     * The accumulated distance from {@code q} to the point at {@code coords[base .. base + k)},
     * axis 0 first; as soon as a partial value exceeds {@code bound}, that partial value (the
     * point is out of reach, and the rest need not be summed).
     */
    double accumulated(double[] q, double[] coords, int base, double bound) {
        int k = q.length;
        double acc = 0;
        switch (kind) {
            case EUCLIDEAN_KIND -> {
                for (int a = 0; a < k; a++) {
                    double d = q[a] - coords[base + a];
                    acc += d * d;
                    if (acc > bound) return acc;
                }
            }
            case CHEBYSHEV_KIND -> {
                for (int a = 0; a < k; a++) {
                    acc = Math.max(acc, Math.abs(q[a] - coords[base + a]));
                    if (acc > bound) return acc;
                }
            }
            default -> {
                for (int a = 0; a < k; a++) {
                    acc += term(q[a] - coords[base + a]);
                    if (acc > bound) return acc;
                }
            }
        }
        return acc;
    }

    /**
     * The true distance of an accumulated one: its p-th root.
     *
     * @param accumulated an accumulated distance, {@code sum |d_a|^p} (for p = infinity, {@code max |d_a|})
     * @return the true distance
     */
    public double distance(double accumulated) {
        return switch (kind) {
            case EUCLIDEAN_KIND -> Math.sqrt(accumulated);
            case MANHATTAN_KIND, CHEBYSHEV_KIND -> accumulated;
            default -> Math.pow(accumulated, 1 / p);
        };
    }

    /**
     * The accumulated form of a true distance: its p-th power.
     *
     * @param distance a true distance
     * @return its accumulated form, as the queries compare distances
     */
    public double accumulated(double distance) {
        return switch (kind) {
            case EUCLIDEAN_KIND -> distance * distance;
            case MANHATTAN_KIND, CHEBYSHEV_KIND -> distance;
            default -> Math.pow(distance, p);
        };
    }

    @Override public String toString() {
        return kind == EUCLIDEAN_KIND ? "euclidean" : kind == MANHATTAN_KIND ? "manhattan"
                : kind == CHEBYSHEV_KIND ? "chebyshev" : "minkowski(p=" + p + ")";
    }
}
