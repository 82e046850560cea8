package org.kdtree.traverse;

import org.kdtree.geom.Ray;

/**
 * The two queries a ray tracer needs, answered by a kd-tree traversal or by brute force.
 * Instances may keep per-query scratch state: use one per thread.
 */
public interface RayQuery {
    /**
     * The closest hit with {@code tMin <= t <= tMax}: written to {@code hit} (reset first),
     * returns whether there is one.
     */
    boolean closestHit(Ray ray, double tMin, double tMax, Hit hit);

    /** Whether anything is hit with {@code tMin <= t <= tMax} (shadow rays: may stop at the first). */
    boolean anyHit(Ray ray, double tMin, double tMax);
}
