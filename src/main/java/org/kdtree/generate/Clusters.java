package org.kdtree.generate;

import java.util.Random;

/**
 * What "clustered" means for every generated scene: a few centres placed uniformly in a cube,
 * and members Gaussian around them. Shapes, triangles and points are clustered by this one
 * recipe; what a member becomes (a point, a small triangle at it) is the caller's.
 */
final class Clusters {
    private final double[] centres;
    private final int count, dimension;

    private Clusters(double[] centres, int count, int dimension) {
        this.centres = centres;
        this.count = count;
        this.dimension = dimension;
    }

    /**
     * Draws {@code count} centres uniformly in {@code [lo, hi]^dimension}, centre by centre.
     *
     * @param random the scene's generator
     * @param count how many clusters
     * @param dimension coordinates per centre
     * @param lo the cube's lower corner on every axis
     * @param hi the cube's upper corner on every axis
     * @return the clusters
     */
    static Clusters draw(Random random, int count, int dimension, double lo, double hi) {
        double[] c = new double[count * dimension];
        for (int i = 0; i < c.length; i++) c[i] = lo + (hi - lo) * random.nextDouble();
        return new Clusters(c, count, dimension);
    }

    /** {@return a cluster chosen at random, each as likely} */
    int pick(Random random) {
        return random.nextInt(count);
    }

    /** {@return the number of clusters} */
    int count() {
        return count;
    }

    /**
     * Writes a member of {@code cluster}: its centre plus a Gaussian offset of standard deviation
     * {@code sigma} on each axis, axis by axis.
     *
     * @param random the scene's generator
     * @param cluster which cluster
     * @param sigma the spread
     * @param dest receives {@code dimension} coordinates from {@code at}
     * @param at where in {@code dest}
     */
    void member(Random random, int cluster, double sigma, double[] dest, int at) {
        for (int a = 0; a < dimension; a++) dest[at + a] = centres[cluster * dimension + a] + sigma * random.nextGaussian();
    }
}
