package org.kdtree.traverse;

import org.kdtree.geom.Ray;

/**
 * Ray tests against numbered primitives: what the traversal adds to the builders' view.
 * Implementations must be safe for concurrent use and allocate nothing per call.
 */
public interface Intersector {
    /** k, the dimension. */
    int dimension();

    /** The number of primitives. */
    int size();

    /**
     * Tests primitive {@code i}. If the ray meets it at a parameter t with
     * {@code tMin <= t <= tMax} and {@code t < hit.t}, records primitive, t and hit data in
     * {@code hit} and returns true; otherwise leaves {@code hit} untouched and returns false.
     * A ray meeting a primitive exactly on an edge or vertex hits it; degenerate primitives
     * are never hit.
     */
    boolean intersect(int i, Ray ray, double tMin, double tMax, Hit hit);
}
