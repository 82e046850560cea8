package org.kdtree.tradeoff;

import java.util.Locale;
import org.kdtree.generate.Points;
import org.kdtree.shape.PointsKd;

/**
 * The point sets a nearest-neighbour study can make for itself when the user has no data: the
 * two kinds of {@code --generate}, drawn by {@link Points} (seeded, the same on every machine).
 * Query points are drawn from the same distribution as the data, from a separate stream.
 */
public enum GeneratedPoints {
    /** {@link Points#uniform Uniform} in the unit cube: the case kd-trees degrade on as the dimension grows. */
    UNIFORM,
    /** {@link Points#clustered Ten Gaussian clusters} in the unit cube: low density away from the clusters, as in much real data. */
    CLUSTERED;

    /**
     * The kind named {@code name} ("uniform", "clustered"; any case), or an error listing both.
     *
     * @param name the kind's name, as given to {@code --generate}
     * @return the kind
     * @throws IllegalArgumentException if {@code name} names neither kind
     */
    public static GeneratedPoints named(String name) {
        for (GeneratedPoints g : values()) if (g.label().equals(name.toLowerCase(Locale.ROOT))) return g;
        throw new IllegalArgumentException("the kind of generated points must be uniform or clustered, got '" + name + "'");
    }

    /** {@return the lower-case name used on the command line and in captions} */
    public String label() {
        return name().toLowerCase(Locale.ROOT);
    }

    /**
     * {@code n} data points of {@code dimension} coordinates.
     *
     * @param n         how many points
     * @param dimension coordinates per point
     * @param seed      the seed; the same seed gives the same points
     * @return the points
     */
    public PointsKd points(int n, int dimension, long seed) {
        return this == UNIFORM ? Points.uniform(n, dimension, seed) : Points.clustered(n, dimension, seed);
    }

    /**
     * {@code count} query points from the distribution of {@link #points} with the same seed.
     *
     * @param count     how many points
     * @param dimension coordinates per point
     * @param seed      the data's seed (a separate stream is drawn from it)
     * @return the query points
     */
    public PointsKd queries(int count, int dimension, long seed) {
        return this == UNIFORM ? Points.uniformQueries(count, dimension, seed) : Points.clusteredQueries(count, dimension, seed);
    }
}
