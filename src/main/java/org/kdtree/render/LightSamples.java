package org.kdtree.render;

import java.util.Arrays;

/**
 * The light samples of one hit point (one of a {@link Shading}'s records), in the lights' order:
 * per sample, its slot (a light's sample: an area light has one per sample, other lights one),
 * the light it brings, and, unless its light casts no shadows, the shadow ray that may block it.
 * The arrays grow with the most samples a point has needed and are kept: nothing is allocated per
 * point.
 */
final class LightSamples {
    private int size;
    /** Per sample: its slot, whether a shadow ray may block it, and that ray's end ({@code 0 <= t <= tMax}). */
    int[] slot = new int[0];
    boolean[] shadowed = new boolean[0];
    double[] tMax = new double[0];
    /** Per sample (3 each): the light it brings when not blocked. */
    double[] light = new double[0];
    /** Per sample: its shadow ray (when {@link #shadowed}). */
    final RayColumns ray = new RayColumns();

    /** {@return how many samples it holds} */
    int size() { return size; }

    /** Empties it. */
    void clear() { size = 0; }

    /** Adds the light (r, g, b) of sample {@code slot}, with no shadow ray yet; returns its index. */
    int add(int slot, double r, double g, double b) {
        if (size == this.slot.length) grow(Math.max(2 * size, 4));
        int i = size++;
        this.slot[i] = slot;
        shadowed[i] = false;
        light[3 * i] = r;
        light[3 * i + 1] = g;
        light[3 * i + 2] = b;
        return i;
    }

    /** Puts sample {@code i} behind the shadow ray {@code o + t d}, {@code 0 <= t <= tMax}. */
    void shadowRay(int i, double[] o, double[] d, double tMax) {
        shadowed[i] = true;
        ray.set(i, o, d);
        this.tMax[i] = tMax;
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
        tMax = Arrays.copyOf(tMax, n);
        light = Arrays.copyOf(light, 3 * n);
        ray.grow(n);
    }
}
