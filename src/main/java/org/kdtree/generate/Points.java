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

    private static PointsKd members(Clusters clusters, int n, int k, Random r) {
        double[] c = new double[Math.multiplyExact(n, k)];
        for (int i = 0; i < n; i++) clusters.member(r, clusters.pick(r), SPREAD, c, i * k);
        return new PointsKd(k, c);
    }
}
