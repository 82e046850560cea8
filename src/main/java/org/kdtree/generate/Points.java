package org.kdtree.generate;

import java.util.Random;
import org.kdtree.shape.PointsKd;

/**
 * Generated k-D point sets: uniform, clustered, duplicated and on a grid, and query points drawn
 * like the data from a stream of their own. The nearest-neighbour study, the point-query
 * benchmark and the point-query tests draw from here.
 */
public final class Points {
    /** The clustered sets' clusters, and their standard deviation per axis. */
    private static final int CLUSTERS = 10;
    private static final double SPREAD = 0.02;

    /** The names of {@link #named}'s sets, as {@code --generate} takes them. */
    public static final java.util.List<String> NAMES = java.util.List.of("uniform", "clustered");

    private Points() {
    }

    /**
     * The set of a name, one per name as {@link Shapes#named} and {@link Meshes#named} have theirs:
     * a nearest-neighbour study draws its data from here when the user has none.
     *
     * @param name "uniform" ({@link #uniform}) or "clustered" ({@link #clustered}), any case
     * @param n    how many points
     * @param k    coordinates per point
     * @param seed the seed; the same seed gives the same points
     * @return the points
     * @throws IllegalArgumentException naming both sets if {@code name} names neither
     */
    public static PointsKd named(String name, int n, int k, long seed) {
        return clustered(name) ? clustered(n, k, seed) : uniform(n, k, seed);
    }

    /**
     * Query points drawn like {@link #named}'s set of the same name and seed, from a stream of their own.
     *
     * @param name  "uniform" or "clustered", any case
     * @param count how many points
     * @param k     coordinates per point
     * @param seed  the data's seed
     * @return the query points
     * @throws IllegalArgumentException naming both sets if {@code name} names neither
     */
    public static PointsKd namedQueries(String name, int count, int k, long seed) {
        return clustered(name) ? clusteredQueries(count, k, seed) : uniformQueries(count, k, seed);
    }

    private static boolean clustered(String name) {
        String lower = name.toLowerCase(java.util.Locale.ROOT);
        if (!NAMES.contains(lower))
            throw new IllegalArgumentException("the kind of generated points must be uniform or clustered, got '" + name + "'");
        return lower.equals("clustered");
    }

    /**
     * {@code n} points uniform in the unit cube: the case kd-trees degrade on as the dimension grows.
     *
     * @param n how many points
     * @param k coordinates per point
     * @param seed the random seed
     * @return the points
     */
    public static PointsKd uniform(int n, int k, long seed) {
        Random r = new Random(seed);
        double[] c = new double[Math.multiplyExact(n, k)];
        for (int i = 0; i < c.length; i++) c[i] = r.nextDouble();
        return new PointsKd(k, c);
    }

    /**
     * {@code n} points in ten Gaussian clusters ({@code Clusters}: standard deviation 0.02 per
     * axis, centres uniform in the unit cube, each point's cluster drawn at random): low density
     * away from the clusters, as in much real data.
     *
     * @param n how many points
     * @param k coordinates per point
     * @param seed the random seed
     * @return the points
     */
    public static PointsKd clustered(int n, int k, long seed) {
        Random r = new Random(seed);
        return members(Clusters.draw(r, CLUSTERS, k, 0, 1), n, k, r);
    }

    /**
     * {@code count} query points from the distribution of {@link #clustered clustered(n, k, seed)}:
     * the same cluster centres, the members drawn from a separate stream.
     *
     * @param count how many points
     * @param k coordinates per point
     * @param seed the data's seed
     * @return the query points
     */
    public static PointsKd clusteredQueries(int count, int k, long seed) {
        return members(Clusters.draw(new Random(seed), CLUSTERS, k, 0, 1), count, k, new Random(~seed));
    }

    /**
     * {@code count} query points from the distribution of {@link #uniform uniform(n, k, seed)}, from a separate stream.
     *
     * @param count how many points
     * @param k coordinates per point
     * @param seed the data's seed
     * @return the query points
     */
    public static PointsKd uniformQueries(int count, int k, long seed) {
        return uniform(count, k, ~seed);
    }

    /**
     * {@code n} points that are seven distinct points (uniform in the unit cube), each repeated
     * many times: distance ties at 0 and coincident points.
     *
     * @param n how many points
     * @param k coordinates per point
     * @param seed the random seed
     * @return the points
     */
    public static PointsKd duplicates(int n, int k, long seed) {
        Random r = new Random(seed);
        double[] distinct = new double[7 * k], c = new double[Math.multiplyExact(n, k)];
        for (int i = 0; i < distinct.length; i++) distinct[i] = r.nextDouble();
        for (int i = 0; i < n; i++) System.arraycopy(distinct, r.nextInt(7) * k, c, i * k, k);
        return new PointsKd(k, c);
    }

    /**
     * {@code n} points with integer coordinates 0 to 3: many equal coordinates, points in split
     * planes, many equal distances.
     *
     * @param n how many points
     * @param k coordinates per point
     * @param seed the random seed
     * @return the points
     */
    public static PointsKd grid(int n, int k, long seed) {
        Random r = new Random(seed);
        double[] c = new double[Math.multiplyExact(n, k)];
        for (int i = 0; i < c.length; i++) c[i] = r.nextInt(4);
        return new PointsKd(k, c);
    }

    /**
     * {@code n} points near a circle: radius 0.4 about the unit cube's centre in the plane of
     * the first two axes, every coordinate then moved by Gaussian noise of standard deviation
     * {@code noise} (a 1-D set has no circle: its points lie near 0.1 and 0.9).
     *
     * @param n     how many points
     * @param k     coordinates per point
     * @param noise the noise's standard deviation per axis
     * @param seed  the random seed
     * @return the points
     */
    public static PointsKd ring(int n, int k, double noise, long seed) {
        Random r = new Random(seed);
        double[] c = new double[Math.multiplyExact(n, k)];
        for (int i = 0; i < n; i++) {
            double angle = 2 * Math.PI * r.nextDouble();
            for (int a = 0; a < k; a++) c[i * k + a] = 0.5 + noise * r.nextGaussian();
            c[i * k] += 0.4 * Math.cos(angle);
            if (k > 1) c[i * k + 1] += 0.4 * Math.sin(angle);
        }
        return new PointsKd(k, c);
    }

    /**
     * {@code n} points near a segment through the unit cube, from a random point near one corner
     * to one near the opposite corner, every coordinate moved by Gaussian noise of standard
     * deviation {@code noise}.
     *
     * @param n     how many points
     * @param k     coordinates per point
     * @param noise the noise's standard deviation per axis
     * @param seed  the random seed
     * @return the points
     */
    public static PointsKd line(int n, int k, double noise, long seed) {
        Random r = new Random(seed);
        double[] from = new double[k], to = new double[k], c = new double[Math.multiplyExact(n, k)];
        for (int a = 0; a < k; a++) {
            from[a] = 0.2 * r.nextDouble();
            to[a] = 1 - 0.2 * r.nextDouble();
        }
        for (int i = 0; i < n; i++) {
            double t = r.nextDouble();
            for (int a = 0; a < k; a++) c[i * k + a] = from[a] + t * (to[a] - from[a]) + noise * r.nextGaussian();
        }
        return new PointsKd(k, c);
    }

    /**
     * {@code n} points at the nodes of a regular grid of {@code side} nodes per axis filling the
     * unit cube, each node taken once (in random order; again only once all are taken), each
     * coordinate then moved by Gaussian noise of standard deviation {@code jitter} times the
     * grid's spacing: a lattice, not a uniform sample.
     *
     * @param n      how many points
     * @param k      coordinates per point
     * @param side   nodes per axis, at least 2, at most 2<sup>24</sup> nodes in all
     * @param jitter the noise's standard deviation, as a share of the spacing
     * @param seed   the random seed
     * @return the points
     */
    public static PointsKd jitteredGrid(int n, int k, int side, double jitter, long seed) {
        double nodes = Math.pow(side, k);
        if (side < 2 || nodes > 1 << 24)
            throw new IllegalArgumentException("a grid needs 2 nodes per axis or more and 2^24 nodes or fewer, got " + side + "^" + k);
        Random r = new Random(seed);
        int[] order = new int[(int) nodes];
        for (int i = 0; i < order.length; i++) order[i] = i;
        double spacing = 1.0 / (side - 1);
        double[] c = new double[Math.multiplyExact(n, k)];
        for (int i = 0; i < n; i++) {
            int pick = i % order.length, swap = pick + r.nextInt(order.length - pick);   // Fisher-Yates, as far as needed
            int node = order[swap];
            order[swap] = order[pick];
            order[pick] = node;
            for (int a = 0; a < k; a++, node /= side) c[i * k + a] = (node % side + jitter * r.nextGaussian()) * spacing;
        }
        return new PointsKd(k, c);
    }

    private static PointsKd members(Clusters clusters, int n, int k, Random r) {
        double[] c = new double[Math.multiplyExact(n, k)];
        for (int i = 0; i < n; i++) clusters.member(r, clusters.pick(r), SPREAD, c, i * k);
        return new PointsKd(k, c);
    }
}
