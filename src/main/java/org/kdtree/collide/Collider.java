package org.kdtree.collide;

/**
 * Exact sphere tests against numbered primitives: what collision detection adds to the builders'
 * view of a scene, as {@code traverse.Intersector} adds ray tests. In 2-D the sphere is a circle.
 *
 * <p>Contacts are closed everywhere: a sphere at distance exactly r touches, and so does a moving
 * sphere that only grazes an edge or a vertex (its path tangent to the capsule or vertex sphere).
 * Implementations must be safe for concurrent use and allocate nothing per call; points are
 * passed as arrays of length {@link #dimension()} (or more), {@code out} has length at least 3.
 */
public interface Collider {
    /** k, the dimension: 2 or 3. */
    int dimension();

    /** The number of primitives. */
    int size();

    /**
     * The squared distance from {@code p} to primitive {@code i} (0 inside a filled one); the
     * closest point of the primitive goes to {@code out[0..k)} unless {@code out} is null.
     * +infinity for a zero-area triangle or rectangle: like rays, spheres never touch those.
     */
    double closestPoint(int i, double[] p, double[] out);

    /**
     * The first contact of a sphere of radius {@code r} whose centre moves along
     * {@code s + t d}: the smallest t in [0, tMax] with distance(s + t d, primitive i) <= r, or
     * +infinity when there is none. A sphere already touching at t = 0 answers 0; a zero
     * {@code d} answers 0 or +infinity.
     */
    double firstContact(int i, double[] s, double[] d, double r, double tMax);

    /**
     * The primitive's own unit normal, for a contact where the centre lies on the primitive (radius
     * 0, or a start inside), written to {@code out}; false when it has none (a point, a filled
     * 2-D shape, a zero-area triangle). Any of its two orientations.
     */
    default boolean surfaceNormal(int i, double[] out) {
        return false;
    }
}
