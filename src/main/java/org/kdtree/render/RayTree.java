package org.kdtree.render;

import java.util.Arrays;
import org.kdtree.accel.RayPacket;

/**
 * The ray trees of one block's camera sample, breadth first: its camera rays first, then each
 * level's reflection and refraction rays after the level that cast them, so that a level's rays
 * are traced together as packets and a parent always comes before its children. Per node: its
 * ray, the block's pixel and the point of the ray tree it belongs to (1 the camera ray, {@code 2n}
 * node {@code n}'s reflection, {@code 2n + 1} its refraction, as the random streams count them),
 * the path's weight, its closest hit, and what its {@link Shading} records: the emitted and ambient
 * light, whether it is lit (its light samples kept in {@link Shadows} under the node's index), the
 * reflection's and refraction's weights and nodes. {@link #colour} then sums a node's colour in
 * the order {@link Shading} gives, the recursive tracer's. The arrays grow with the largest tree a block has needed
 * and are kept: nothing is allocated per ray.
 */
final class RayTree {
    private int size;
    /** Per node: the block's pixel, the ray tree's point, and its reflection's and refraction's nodes (-1: none). */
    int[] pixel = new int[0], reflection = pixel, refraction = pixel;
    long[] point = new long[0];
    /** Per node: the path's weight. */
    double[] weight = new double[0];
    /** Per node: its ray. */
    final RayColumns ray = new RayColumns();
    /** Per node: its ray's closest hit ({@link RayPacket}'s fields). */
    int[] primitive = pixel;
    double[] t = weight, u = weight, v = weight;
    /** Per node (3 each): emitted plus ambient light (or the background), the reflection's and refraction's weights, the colour. */
    double[] base = weight, kr = weight, kt = weight, colour = weight;
    boolean[] lit = new boolean[0];
    /** Per node: its colour is known already (traced depth first, past the block's budget): not traced nor shaded with its level. */
    boolean[] finished = lit;
    private final double[] light = new double[3];

    /** {@return how many nodes it holds} */
    int size() { return size; }

    /** Empties it. */
    void clear() { size = 0; }

    /**
     * Adds a node whose ray is {@code o + t d} and returns its index.
     *
     * @param pixel the block's pixel
     * @param point the point of the ray tree
     * @param weight the path's weight
     */
    int add(int pixel, long point, double weight, double[] o, double[] d) {
        if (size == this.pixel.length) grow(Math.max(2 * size, RayPacket.CAPACITY));
        int n = size++;
        this.pixel[n] = pixel;
        this.point[n] = point;
        this.weight[n] = weight;
        ray.set(n, o, d);
        reflection[n] = refraction[n] = -1;
        lit[n] = finished[n] = false;
        return n;
    }

    /** Makes node {@code n} finished, its colour {@code c} (its subtree traced depth first). */
    void finish(int n, double[] c) {
        finished[n] = true;
        System.arraycopy(c, 0, base, 3 * n, 3);
    }

    /** {@return the kind of node {@code n}'s ray} */
    RayKind kind(int n) {
        long p = point[n];
        return p == 1 ? RayKind.CAMERA : (p & 1) == 0 ? RayKind.REFLECTION : RayKind.REFRACTION;
    }

    /** Makes node {@code child} the ray {@code r} that node {@code parent} sends on, its colour to be added with {@code r}'s weight. */
    void link(int parent, int child, SecondaryRay r) {
        if (r.kind == RayKind.REFLECTION) reflection[parent] = child;
        else refraction[parent] = child;
        System.arraycopy(r.weight, 0, r.kind == RayKind.REFLECTION ? kr : kt, 3 * parent, 3);
    }

    /** Records packet ray {@code r}'s closest hit as node {@code n}'s. */
    void record(int n, RayPacket p, int r) {
        primitive[n] = p.primitive[r];
        t[n] = p.t[r];
        u[n] = p.u[r];
        v[n] = p.v[r];
    }

    /**
     * Sums each node's colour, children before parents: its emitted and ambient light, its direct
     * light ({@code shadows}, traced), then the reflection's colour times its weight and the
     * refraction's, each step rounded as the recursive tracer ({@link WhittedTracer}) rounds it.
     */
    void colour(Shadows shadows) {
        for (int n = size - 1; n >= 0; n--) {
            int b = 3 * n;
            double c0 = base[b], c1 = base[b + 1], c2 = base[b + 2];
            if (lit[n]) {
                shadows.sum(n, light);
                c0 = c0 + light[0];
                c1 = c1 + light[1];
                c2 = c2 + light[2];
            }
            int r = reflection[n];
            if (r >= 0) {
                c0 = c0 + kr[b] * colour[3 * r];
                c1 = c1 + kr[b + 1] * colour[3 * r + 1];
                c2 = c2 + kr[b + 2] * colour[3 * r + 2];
            }
            int f = refraction[n];
            if (f >= 0) {
                c0 = c0 + kt[b] * colour[3 * f];
                c1 = c1 + kt[b + 1] * colour[3 * f + 1];
                c2 = c2 + kt[b + 2] * colour[3 * f + 2];
            }
            colour[b] = c0;
            colour[b + 1] = c1;
            colour[b + 2] = c2;
        }
    }

    private void grow(int n) {
        pixel = Arrays.copyOf(pixel, n);
        reflection = Arrays.copyOf(reflection, n);
        refraction = Arrays.copyOf(refraction, n);
        primitive = Arrays.copyOf(primitive, n);
        point = Arrays.copyOf(point, n);
        lit = Arrays.copyOf(lit, n);
        finished = Arrays.copyOf(finished, n);
        weight = Arrays.copyOf(weight, n);
        ray.grow(n);
        t = Arrays.copyOf(t, n);
        u = Arrays.copyOf(u, n);
        v = Arrays.copyOf(v, n);
        base = Arrays.copyOf(base, 3 * n);
        kr = Arrays.copyOf(kr, 3 * n);
        kt = Arrays.copyOf(kt, 3 * n);
        colour = Arrays.copyOf(colour, 3 * n);
    }
}
