package org.kdtree.accel;

import org.kdtree.geom.Ray;
import org.kdtree.geom.Tolerance;

/**
 * The slab clip of a ray against an axis-aligned box, in one place so that every traversal that
 * clips this way rounds the same way ({@link Tolerance#TRAVERSAL_SLACK}): the two listening
 * traversals ({@link #clip}: the kd-tree's {@code Traverser} to its scene box, the bounding volume
 * hierarchy's {@code BvhTraverser} to its node boxes) and the kd-tree's fast loops ({@link #clip3}
 * on a ray's origin and inverse direction: {@code MeshTraversal} and the packet loop, to the scene
 * box). The BVH's single-ray and packet kernels test their boxes with the same slack in a form of
 * their own: a non-negative interval widened by factors ({@code t0 * (1 - slack) <= t1 * (1 +
 * slack)}) instead of by {@code |t| * slack}.
 */
public final class SlabClip {
    private SlabClip() {
    }

    /**
     * The slab test of the listening traversals (the kd-tree's scene box, a bounding volume
     * hierarchy's node boxes): {@code [tMin, tMax]} clipped to the box, widened by
     * the slack, into {@code interval}. A NaN slab bound (origin on a face of a flat box,
     * direction 0 on that axis) constrains nothing.
     *
     * @param ray      the ray, of the box's dimension k
     * @param box      holds the box from {@code at}: k minima, then k maxima
     * @param at       where the box starts in {@code box}
     * @param tMin     the start of the ray's range
     * @param tMax     its end
     * @param interval receives where the ray enters the box (index 0) and leaves it (index 1)
     * @return whether anything of the range is left
     */
    public static boolean clip(Ray ray, double[] box, int at, double tMin, double tMax, double[] interval) {
        int k = ray.dimension();
        double t0 = tMin, t1 = tMax;
        for (int a = 0; a < k; a++) {
            double inv = ray.inverseDirection(a), o = ray.origin(a);
            double tNear = (box[at + a] - o) * inv, tFar = (box[at + k + a] - o) * inv;
            if (inv < 0) { double s = tNear; tNear = tFar; tFar = s; }
            if (tNear > t0) t0 = tNear;
            if (tFar < t1) t1 = tFar;
        }
        return widen(t0, t1, tMin, tMax, interval);
    }

    /**
     * {@link #clip}'s operations, in its order, for a 3-D ray given by its origin and inverse
     * direction (the fast loops keep them in locals or in a packet's columns, not in a {@link Ray}).
     *
     * @param box      3 minima, then 3 maxima
     * @param ox       the origin, x
     * @param oy       the origin, y
     * @param oz       the origin, z
     * @param ix       the inverse direction, x (infinite for a zero component)
     * @param iy       the inverse direction, y
     * @param iz       the inverse direction, z
     * @param tMin     the start of the ray's range
     * @param tMax     its end
     * @param interval receives where the ray enters the box (index 0) and leaves it (index 1)
     * @return whether anything of the range is left
     */
    public static boolean clip3(double[] box, double ox, double oy, double oz, double ix, double iy, double iz, double tMin, double tMax,
                                double[] interval) {
        double t0 = tMin, t1 = tMax, a, b;
        a = (box[0] - ox) * ix; b = (box[3] - ox) * ix;
        if (ix < 0) { double s = a; a = b; b = s; }
        if (a > t0) t0 = a;
        if (b < t1) t1 = b;
        a = (box[1] - oy) * iy; b = (box[4] - oy) * iy;
        if (iy < 0) { double s = a; a = b; b = s; }
        if (a > t0) t0 = a;
        if (b < t1) t1 = b;
        a = (box[2] - oz) * iz; b = (box[5] - oz) * iz;
        if (iz < 0) { double s = a; a = b; b = s; }
        if (a > t0) t0 = a;
        if (b < t1) t1 = b;
        return widen(t0, t1, tMin, tMax, interval);
    }

    /**
     * The one rounding of both clips: the box's {@code [t0, t1]} widened by the slack on each side,
     * kept within the ray's {@code [tMin, tMax]}, into {@code interval}.
     */
    private static boolean widen(double t0, double t1, double tMin, double tMax, double[] interval) {
        interval[0] = Math.max(tMin, t0 - Math.abs(t0) * Tolerance.TRAVERSAL_SLACK);
        interval[1] = Math.min(tMax, t1 + Math.abs(t1) * Tolerance.TRAVERSAL_SLACK);
        return interval[0] <= interval[1];
    }
}
