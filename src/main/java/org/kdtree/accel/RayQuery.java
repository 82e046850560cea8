package org.kdtree.accel;

import org.kdtree.geom.Ray;

/**
 * The two queries a ray tracer needs, answered by a kd-tree traversal or by brute force.
 * Instances may keep per-query scratch state: use one per thread.
 */
public interface RayQuery {
    /**
     * The closest hit with {@code tMin <= t <= tMax}: written to {@code hit} (reset first),
     * returns whether there is one.
     *
     * @param ray  the ray {@code o + t d}
     * @param tMin the start of the interval of t searched
     * @param tMax its end
     * @param hit  receives the closest hit: primitive, t and (u, v)
     * @return whether the ray hits a primitive in the interval
     */
    boolean closestHit(Ray ray, double tMin, double tMax, Hit hit);

    /**
     * Whether anything is hit with {@code tMin <= t <= tMax} (shadow rays: may stop at the first).
     *
     * @param ray  the ray {@code o + t d}
     * @param tMin the start of the interval of t searched
     * @param tMax its end
     * @return whether the ray hits a primitive in the interval
     */
    boolean anyHit(Ray ray, double tMin, double tMax);
}
