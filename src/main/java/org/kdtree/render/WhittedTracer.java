package org.kdtree.render;

import org.kdtree.accel.Hit;
import org.kdtree.accel.RayQuery;
import org.kdtree.geom.Ray;
import org.kdtree.scene.Scene;

/**
 * Whitted's recursive ray tracer, one pixel at a time: a camera ray per sample, and at each hit
 * what the {@link Shader} records followed at once, depth first: each light sample's shadow ray
 * cast (any hit) and its light added unless blocked, then the reflection and refraction rays
 * traced in turn, each one's colour added with its weight. The reference the block tracer
 * ({@link BlockTracer}) is held to, and the one docs/rendering.md walks through.
 *
 * <p>One per thread: it owns its ray, hit, sampler and per level of the ray tree one {@link
 * Shading} and one colour, so that tracing allocates nothing.
 */
final class WhittedTracer {
    private final Scene scene;
    private final Shader shader;
    private final RayQuery query;
    private final RayCounts counts;
    private final PixelSampler sampler;
    private final Ray ray = new Ray(3);
    private final Hit hit = new Hit();
    private final double[] cameraDir = new double[3], light = new double[3], sample = new double[3];
    /** Per depth of the ray tree: the records of its hit and its colour, kept while the rays below it are traced. */
    private final Shading[] shading;
    private final double[][] colour;

    /**
     * A tracer for one thread.
     *
     * @param scene  the scene
     * @param shader shades the scene's hits (it may be shared with this thread's block tracer)
     * @param depth  the scene's depth limit ({@link EffectPlan#maxDepth})
     * @param query  this thread's ray queries
     * @param counts counts the rays cast
     */
    WhittedTracer(Scene scene, Shader shader, int depth, RayQuery query, RayCounts counts) {
        this.scene = scene;
        this.shader = shader;
        this.query = query;
        this.counts = counts;
        this.sampler = new PixelSampler(scene);
        LightSamples lights = new LightSamples();      // read before the secondary rays are traced: one serves every level
        shading = new Shading[depth + 1];
        colour = new double[depth + 1][3];
        for (int d = 0; d <= depth; d++) shading[d] = new Shading(lights);
    }

    /**
     * Writes the mean radiance of pixel (x, y) over the scene's samples per pixel to {@code rgb}.
     *
     * @param x   the pixel's column
     * @param y   the pixel's row
     * @param rgb receives the linear red, green and blue radiance
     */
    void pixel(int x, int y, double[] rgb) {
        int n = scene.samplesPerPixel();
        double r = 0, g = 0, b = 0;
        for (int i = 0; i < n; i++) {
            sampler.startCameraSample(x, y, i, n, cameraDir);
            double[] c = trace(sampler.eye(), cameraDir, 1, 1, RayKind.CAMERA);
            r = r + c[0];
            g = g + c[1];
            b = b + c[2];
        }
        double mean = 1.0 / n;
        rgb[0] = r * mean;
        rgb[1] = g * mean;
        rgb[2] = b * mean;
    }

    /**
     * Writes to {@code rgb} the colour of one ray of pixel (x, y)'s camera sample {@code sample}:
     * the ray {@code o + t d} at {@code point} of the sample's ray tree, with its path's weight.
     * The block tracer's way to finish a ray tree depth first.
     */
    void trace(int x, int y, int sample, double[] o, double[] d, long point, double weight, RayKind kind, double[] rgb) {
        sampler.startSample(x, y, sample);
        System.arraycopy(trace(o, d, point, weight, kind), 0, rgb, 0, 3);
    }

    /** {@return the radiance arriving at {@code origin} from direction {@code -dir}}: the ray's colour, at {@code point} of the ray tree. */
    private double[] trace(double[] origin, double[] dir, long point, double weight, RayKind kind) {
        counts.add(kind);
        ray.set(origin[0], origin[1], origin[2], dir[0], dir[1], dir[2]);
        boolean found = query.closestHit(ray, 0, Double.POSITIVE_INFINITY, hit);
        int depth = Shader.depth(point);
        Shading s = shading[depth];
        shader.shade(found, hit, dir, point, weight, sampler, s);
        double[] c = colour[depth];
        System.arraycopy(s.base, 0, c, 0, 3);
        if (s.lit) {
            directLight(s.lights);
            for (int i = 0; i < 3; i++) c[i] = c[i] + light[i];
        }
        follow(s.reflection, point, c);
        follow(s.refraction, point, c);
        return c;
    }

    /**
     * Sums into {@link #light}, from 0 in the samples' order, the light of the samples whose shadow
     * rays reach the light: the shader's BRDF is evaluated for those only.
     */
    private void directLight(LightSamples samples) {
        double l0 = 0, l1 = 0, l2 = 0;
        for (int i = 0, n = samples.size(); i < n; i++) {
            if (samples.shadowed(i) && blocked(samples, i)) continue;
            shader.reflected(samples, i, sample);
            l0 = l0 + sample[0];
            l1 = l1 + sample[1];
            l2 = l2 + sample[2];
        }
        light[0] = l0;
        light[1] = l1;
        light[2] = l2;
    }

    /** Casts sample {@code i}'s shadow ray: {@return whether anything blocks it} */
    private boolean blocked(LightSamples samples, int i) {
        counts.add(RayKind.SHADOW);
        return query.anyHit(samples.shadowRay(i, ray), 0, samples.end(i));
    }

    /** Adds to {@code c} the colour of {@code r}, when followed, times its weight. */
    private void follow(SecondaryRay r, long point, double[] c) {
        if (!r.followed) return;
        double[] rc = trace(r.origin, r.direction, r.point(point), r.pathWeight, r.kind);
        for (int i = 0; i < 3; i++) c[i] = c[i] + r.weight[i] * rc[i];
    }
}
