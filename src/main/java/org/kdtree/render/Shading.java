package org.kdtree.render;

/**
 * What the {@link Shader} makes of one ray's hit, as records for a tracer to consume: the light the
 * surface gives whatever else happens (emitted plus ambient, or the background where the ray hit
 * nothing); its light samples, each with the shadow ray that may block it; and the reflection and
 * refraction rays to follow, each with its weight. Its colour is then, in this order and rounded
 * step by step: {@link #base}, plus the unblocked light samples summed from 0 (when {@link #lit}),
 * plus the reflection's colour times its weight, plus the refraction's. The recursive tracer
 * ({@link WhittedTracer}) and the block tracer ({@link BlockTracer}) both sum it so.
 */
final class Shading {
    /** Emitted plus ambient light of the surface hit, or the background where the ray hit nothing. */
    final double[] base = new double[3];
    /** Whether the lights shade the surface: its direct light is then the sum of its {@link #lights} not blocked. */
    boolean lit;
    /** The light samples of the hit point, in the lights' order. */
    final LightSamples lights;
    /** The mirror reflection and the refraction, each followed or not. */
    final SecondaryRay reflection = new SecondaryRay(RayKind.REFLECTION), refraction = new SecondaryRay(RayKind.REFRACTION);

    /**
     * @param lights where the light samples go (a tracer that reads them before it follows the
     *               secondary rays may give every level of its ray tree the same one)
     */
    Shading(LightSamples lights) {
        this.lights = lights;
    }

    /** Forgets the last hit's records. */
    void clear() {
        lit = false;
        lights.clear();
        reflection.followed = false;
        refraction.followed = false;
    }
}
