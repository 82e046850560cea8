package org.kdtree.render;

import java.util.SplittableRandom;

/**
 * Random numbers seeded per pixel, so that a pixel's samples do not depend on which thread
 * renders it or in which order: images are reproducible and identical across thread counts.
 */
final class PixelSampler {
    private final long seed;
    private SplittableRandom random;

    /**
     * A sampler whose sequences derive from {@code seed}.
     *
     * @param seed the scene's base seed
     */
    public PixelSampler(long seed) {
        this.seed = seed;
    }

    /**
     * Restarts the sequence for pixel (x, y).
     *
     * @param x the pixel's column
     * @param y the pixel's row
     */
    public void startPixel(int x, int y) {
        random = new SplittableRandom(seed ^ (0x9E3779B97F4A7C15L * (((long) y << 32) | (x & 0xffffffffL))));
    }

    /** {@return the next number in [0, 1)} */
    public double next() { return random.nextDouble(); }

    /**
     * Sample {@code i} of {@code n} over the unit square: the centre for a single sample,
     * stratified jitter when n is a perfect square, plain jitter otherwise. Writes (s, t) to {@code st}.
     * @param i the sample's index, 0 .. n-1
     * @param n the number of samples
     * @param st receives (s, t)
     */
    public void square(int i, int n, double[] st) {
        if (n == 1) {
            st[0] = st[1] = 0.5;
            return;
        }
        int m = (int) Math.round(Math.sqrt(n));
        if (m * m == n) {
            st[0] = (i % m + next()) / m;
            st[1] = (i / m + next()) / m;
        } else {
            st[0] = next();
            st[1] = next();
        }
    }
}
