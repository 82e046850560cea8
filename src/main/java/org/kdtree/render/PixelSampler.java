package org.kdtree.render;

import static org.kdtree.scene.Vectors.set;

import org.kdtree.scene.Camera;
import org.kdtree.scene.Scene;

/**
 * Random numbers in streams of their own, one per pixel, camera sample and point of the ray tree,
 * so that no number depends on which thread renders a pixel, in which order, or whether its rays
 * were traced one at a time or in packets: images are reproducible, identical across thread
 * counts and across the recursive tracer and the block tracer ({@link WhittedTracer}, {@link BlockTracer}).
 *
 * <p>A stream is picked by {@link #startSample} and {@link #startPoint} (a hash of the scene's
 * seed, the pixel, the sample's index and the node of the ray tree) and then steps a 64-bit counter through a bijective mixer
 * (Steele, Lea and Flood's SplitMix64, the generator behind {@link java.util.SplittableRandom}).
 * Two longs of state: nothing is allocated per pixel or per stream.
 *
 * <p>It starts each camera sample's ray too ({@link #startCameraSample}, {@link #eye}): its
 * direction is drawn from the sample's stream, so both tracers take their camera rays from here.
 */
final class PixelSampler {
    /** The odd step of the counter (the golden ratio's 64-bit fraction). */
    private static final long GOLDEN = 0x9E3779B97F4A7C15L;
    private final long seed;
    private final Camera camera;
    /** Where every camera ray starts: the camera's eye, as an array of the sampler's own. */
    private final double[] eye;
    /** The hash of the current camera sample ({@link #startSample}) and the state of the current stream. */
    private long pixelSample, state;
    /** A camera sample's jitter over its pixel. */
    private final double[] st = new double[2];

    /**
     * A sampler of {@code scene}'s camera whose streams derive from the scene's seed.
     *
     * @param scene the scene
     */
    PixelSampler(Scene scene) {
        this.seed = scene.seed();
        this.camera = scene.camera();
        this.eye = set(camera.eye(), new double[3]);
    }

    /** {@return the origin of every camera ray, the camera's eye} (read, never written) */
    double[] eye() { return eye; }

    /**
     * Starts the streams of pixel (x, y)'s camera sample {@code sample}: each point of its ray tree
     * then has a stream of its own ({@link #startPoint}).
     *
     * @param x      the pixel's column
     * @param y      the pixel's row
     * @param sample the camera sample's index in the pixel
     */
    void startSample(int x, int y, int sample) {
        long h = mix(seed ^ GOLDEN * ((long) y << 32 | (x & 0xffffffffL)));
        pixelSample = mix(h + GOLDEN * (sample + 1L));
    }

    /**
     * Starts the stream of point {@code node} of the current camera sample's ray tree (0: the
     * camera ray's jitter; 1: the camera ray's hit; a hit's reflection child is {@code 2 node},
     * its refraction child {@code 2 node + 1}).
     *
     * @param node the point of the ray tree the numbers are for
     */
    void startPoint(long node) {
        state = mix(pixelSample ^ GOLDEN * (node + 1));
    }

    /**
     * Starts the streams of pixel (x, y)'s camera sample {@code i} of {@code n} and writes the
     * direction of its camera ray to {@code dir}: through the pixel's centre for one sample, else
     * jittered ({@link #square}) by the numbers of the ray tree's point 0.
     *
     * @param x      the pixel's column
     * @param y      the pixel's row
     * @param i      the camera sample's index in the pixel
     * @param n      the camera samples per pixel
     * @param dir    receives the unit direction of the camera ray
     */
    void startCameraSample(int x, int y, int i, int n, double[] dir) {
        startSample(x, y, i);
        startPoint(0);
        square(i, n, st);
        camera.direction(x + st[0], y + st[1], dir);
    }

    /** {@return the next number of the stream, in [0, 1)} */
    double next() {
        state += GOLDEN;
        return (mix(state) >>> 11) / (double) (1L << 53);      // 53 random bits, exactly
    }

    /** SplitMix64's finalizer: a bijection of the 64-bit words that spreads every input bit over the output. */
    private static long mix(long z) {
        z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
        z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
        return z ^ (z >>> 31);
    }

    /**
     * Sample {@code i} of {@code n} over the unit square: the centre for a single sample,
     * stratified jitter when n is a perfect square, plain jitter otherwise. Writes (s, t) to {@code st}.
     * @param i the sample's index, 0 .. n-1
     * @param n the number of samples
     * @param st receives (s, t)
     */
    void square(int i, int n, double[] st) {
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
