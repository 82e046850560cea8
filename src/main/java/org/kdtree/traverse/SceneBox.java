package org.kdtree.traverse;

import org.kdtree.geom.Box;
import org.kdtree.geom.Ray;
import org.kdtree.geom.Tolerance;

/**
 * Step 1 of Algorithm 2, for both traversal loops ({@link Traverser}'s and {@link MeshTraversal}'s):
 * the ray is checked, then its range {@code [tMin, tMax]} is clipped to the scene box (the slab
 * test) and widened by the traversal slack. A NaN slab bound (the origin on a face of a flat slab,
 * direction 0 on that axis: 0 * infinity) constrains nothing. Owned by one traverser, like its
 * stack: it holds the clipped range of the last ray.
 */
final class SceneBox {
    private static final double SLACK = Tolerance.TRAVERSAL_SLACK;

    private final double[] lo, hi;
    /** The last clipped range: where the ray enters the scene box and where it leaves. */
    double enter, exit;

    /** @param box the tree's root voxel */
    SceneBox(Box box) {
        lo = box.minCorner();
        hi = box.maxCorner();
    }

    /**
     * Checks the ray and clips {@code [tMin, tMax]} to the box into {@link #enter} and {@link #exit};
     * false when nothing is left.
     */
    boolean clip(Ray ray, double tMin, double tMax) {
        check(ray);
        double t0 = tMin, t1 = tMax;
        for (int a = 0; a < lo.length; a++) {
            double inv = ray.inverseDirection(a), o = ray.origin(a);
            double tNear = (lo[a] - o) * inv, tFar = (hi[a] - o) * inv;
            if (inv < 0) { double s = tNear; tNear = tFar; tFar = s; }
            if (tNear > t0) t0 = tNear;
            if (tFar < t1) t1 = tFar;
        }
        enter = Math.max(tMin, t0 - Math.abs(t0) * SLACK);
        exit = Math.min(tMax, t1 + Math.abs(t1) * SLACK);
        return enter <= exit;
    }

    /** Rejects rays that no query can answer: another dimension, non-finite values or an all-zero direction. */
    private void check(Ray ray) {
        if (ray.dimension() != lo.length)
            throw new IllegalArgumentException("a " + ray.dimension() + "-D ray in a " + lo.length + "-D tree");
        boolean moving = false;
        for (int a = 0; a < ray.dimension(); a++) {
            double o = ray.origin(a), d = ray.direction(a);
            if (!Double.isFinite(o) || !Double.isFinite(d))
                throw new IllegalArgumentException("ray has a non-finite origin or direction: " + ray);
            moving |= d != 0;
        }
        if (!moving) throw new IllegalArgumentException("ray direction is zero: " + ray);
    }
}
