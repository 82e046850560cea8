package org.kdtree.tradeoff;

import java.util.Locale;
import org.kdtree.shape.PointsKd;

/**
 * The point sets a nearest-neighbour study can make for itself when the user has no data,
 * deterministic for a seed (splitmix64, so the same on every machine). Query points are drawn
 * from the same distribution as the data, from a separate stream.
 */
public enum GeneratedPoints {
    /** Uniform in the unit cube: the case kd-trees degrade on as the dimension grows. */
    UNIFORM,
    /**
     * Ten Gaussian clusters (standard deviation 0.02 per axis) around centres uniform in the unit
     * cube: low intrinsic density away from the clusters, as in much real data.
     */
    CLUSTERED;

    private static final int CLUSTERS = 10;
    private static final double SPREAD = 0.02;

    /**
     * The kind named {@code name} ("uniform", "clustered"; any case), or an error listing both.
     *
     * @param name the kind's name, as given to {@code --generate}
     * @return the kind
     * @throws IllegalArgumentException if {@code name} names neither kind
     */
    public static GeneratedPoints named(String name) {
        for (GeneratedPoints g : values()) if (g.label().equals(name.toLowerCase(Locale.ROOT))) return g;
        throw new IllegalArgumentException("--generate must be uniform or clustered, got '" + name + "'");
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
        return draw(n, dimension, seed, new SplitMix64(seed ^ 0x243F6A8885A308D3L));
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
        return draw(count, dimension, seed, new SplitMix64(seed ^ 0x13198A2E03707344L));
    }

    /** The cluster centres depend on the seed only, so data and queries share them. */
    private PointsKd draw(int n, int dimension, long seed, SplitMix64 random) {
        double[] c = new double[Math.multiplyExact(n, dimension)];
        if (this == UNIFORM) {
            for (int i = 0; i < c.length; i++) c[i] = random.nextDouble();
            return new PointsKd(dimension, c);
        }
        double[] centres = centres(dimension, seed);
        for (int i = 0; i < n; i++) {
            int cluster = (int) ((random.nextLong() >>> 1) % CLUSTERS);
            for (int a = 0; a < dimension; a++)
                c[i * dimension + a] = centres[cluster * dimension + a] + SPREAD * gaussian(random);
        }
        return new PointsKd(dimension, c);
    }

    private static double[] centres(int dimension, long seed) {
        SplitMix64 random = new SplitMix64(seed);
        double[] centres = new double[CLUSTERS * dimension];
        for (int i = 0; i < centres.length; i++) centres[i] = random.nextDouble();
        return centres;
    }

    /** A standard normal value (Box-Muller, one of the pair). */
    private static double gaussian(SplitMix64 random) {
        double u = 1 - random.nextDouble(), v = random.nextDouble();
        return Math.sqrt(-2 * Math.log(u)) * Math.cos(2 * Math.PI * v);
    }
}
