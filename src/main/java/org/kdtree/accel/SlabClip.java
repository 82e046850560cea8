package org.kdtree.accel;

import org.kdtree.geom.Ray;
import org.kdtree.geom.Tolerance;

/**
 * The slab clip of a ray against an axis-aligned box, shared by the two listening traversals (the
 * kd-tree's {@code Traverser} clips a ray to its scene box, the bounding volume hierarchy's {@code
 * BvhTraverser} to its node boxes), so that both round the same way ({@link
 * Tolerance#TRAVERSAL_SLACK}). The fast loops clip with the same slack in forms of their own: the
 * kd-tree's {@code MeshTraversal} writes this clip out on its locals; the BVH's wide, pair and
 * packet loops widen a non-negative interval by factors ({@code t0 * (1 - slack) <= t1 * (1 +
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
        interval[0] = Math.max(tMin, t0 - Math.abs(t0) * Tolerance.TRAVERSAL_SLACK);
        interval[1] = Math.min(tMax, t1 + Math.abs(t1) * Tolerance.TRAVERSAL_SLACK);
        return interval[0] <= interval[1];
    }
}
