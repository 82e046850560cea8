package org.kdtree.render;

import java.util.Arrays;
import org.kdtree.geom.Ray;

/**
 * The light samples of one hit point (one of a {@link Shading}'s records), in the lights' order:
 * per sample, its slot (a light's sample: an area light has one per sample, other lights one),
 * the light arriving (its unit direction, its power and its falloff), and, unless its light casts
 * no shadows, the shadow ray that may block it. What the surface makes of that light (the BRDF,
 * {@link Shader#reflected}) is left to the tracer, which asks only for the samples whose shadow
 * rays reach the light: a blocked sample costs its shadow ray and nothing more.
 * A sample's numbers lie together in one array; it grows with the most samples a point has needed
 * and is kept: nothing is allocated per point.
 */
final class LightSamples {
    /** Per sample: unit direction toward the light x, y, z; power r, g, b; falloff; shadow ray origin x, y, z, direction x, y, z; its end. */
    private static final int STRIDE = 14, POWER = 3, FALLOFF = 6, ORIGIN = 7, END = 13;
    private int size;
    private int[] slot = new int[0];
    private boolean[] shadowed = new boolean[0];
    private double[] data = new double[0];

    /** {@return how many samples it holds} */
    int size() { return size; }

    /** Empties it. */
    void clear() { size = 0; }

    /**
     * Adds sample {@code slot}: the light of {@code power} arriving from unit direction {@code
     * toward}, weakened by {@code falloff}, with no shadow ray yet; returns its index.
     */
    int add(int slot, double[] toward, double[] power, double falloff) {
        if (size == this.slot.length) grow(Math.max(2 * size, 4));
        int i = size++, at = STRIDE * i;
        this.slot[i] = slot;
        shadowed[i] = false;
        data[at] = toward[0];
        data[at + 1] = toward[1];
        data[at + 2] = toward[2];
        data[at + POWER] = power[0];
        data[at + POWER + 1] = power[1];
        data[at + POWER + 2] = power[2];
        data[at + FALLOFF] = falloff;
        return i;
    }

    /** Puts sample {@code i} behind the shadow ray {@code o + t d}, {@code 0 <= t <= tMax}. */
    void shadowRay(int i, double[] o, double[] d, double tMax) {
        shadowed[i] = true;
        int at = STRIDE * i;
        data[at + ORIGIN] = o[0];
        data[at + ORIGIN + 1] = o[1];
        data[at + ORIGIN + 2] = o[2];
        data[at + ORIGIN + 3] = d[0];
        data[at + ORIGIN + 4] = d[1];
        data[at + ORIGIN + 5] = d[2];
        data[at + END] = tMax;
    }

    /** {@return sample {@code i}'s slot} */
    int slot(int i) { return slot[i]; }

    /** {@return whether a shadow ray may block sample {@code i}} */
    boolean shadowed(int i) { return shadowed[i]; }

    /** {@return coordinate {@code a} of the unit direction toward sample {@code i}'s light} */
    double toward(int i, int a) { return data[STRIDE * i + a]; }

    /** {@return channel {@code c} (0 red, 1 green, 2 blue) of sample {@code i}'s power} */
    double power(int i, int c) { return data[STRIDE * i + POWER + c]; }

    /** {@return sample {@code i}'s falloff: 1 over the squared distance to a point, 1 for a direction} */
    double falloff(int i) { return data[STRIDE * i + FALLOFF]; }

    /** {@return sample {@code i}'s shadow ray's end: it is {@code o + t d}, {@code 0 <= t <= end}} */
    double end(int i) { return data[STRIDE * i + END]; }

    /** Sets {@code ray} to sample {@code i}'s shadow ray and returns it. */
    Ray shadowRay(int i, Ray ray) {
        int at = STRIDE * i + ORIGIN;
        return ray.set(data[at], data[at + 1], data[at + 2], data[at + 3], data[at + 4], data[at + 5]);
    }

    /** Copies sample {@code i}'s shadow ray into ray {@code e} of {@code to}. */
    void copyShadowRay(int i, RayColumns to, int e) {
        int at = STRIDE * i + ORIGIN;
        to.ox[e] = data[at];
        to.oy[e] = data[at + 1];
        to.oz[e] = data[at + 2];
        to.dx[e] = data[at + 3];
        to.dy[e] = data[at + 4];
        to.dz[e] = data[at + 5];
    }

    /** {@return the shadow rays among its samples} */
    int shadowRays() {
        int n = 0;
        for (int i = 0; i < size; i++) if (shadowed[i]) n++;
        return n;
    }

    private void grow(int n) {
        slot = Arrays.copyOf(slot, n);
        shadowed = Arrays.copyOf(shadowed, n);
        data = Arrays.copyOf(data, STRIDE * n);
    }
}
