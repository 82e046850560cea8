package org.kdtree.accel;

import org.kdtree.geom.Ray;

/**
 * Ray tests against numbered primitives: what the traversal adds to the builders' view.
 * Implementations must be safe for concurrent use and allocate nothing per call.
 */
public interface Intersector {
    /** {@return k, the dimension} */
    int dimension();

    /** {@return the number of primitives} */
    int size();

    /**
     * Tests primitive {@code i}. If the ray meets it at a parameter t with
     * {@code tMin <= t <= tMax} and {@code t < hit.t}, records primitive, t and hit data in
     * {@code hit} and returns true; otherwise leaves {@code hit} untouched and returns false.
     * A ray meeting a primitive exactly on an edge or vertex hits it; degenerate primitives
     * are never hit.
     * @param i the primitive's index
     * @param ray the ray
     * @param tMin the start of the ray's range
     * @param tMax the end of the ray's range
     * @param hit the closest hit so far; updated on a closer hit
     * @return whether a closer hit was recorded
     */
    boolean intersect(int i, Ray ray, double tMin, double tMax, Hit hit);
}
