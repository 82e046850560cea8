package org.kdtree.collide;

/**
 * Exact sphere tests against numbered primitives: what collision detection adds to the builders'
 * view of a scene, as {@code accel.Intersector} adds ray tests. In 2-D the sphere is a circle.
 *
 * <p>Contacts are closed everywhere: a sphere at distance exactly r touches, and so does a moving
 * sphere that only grazes an edge or a vertex (its path tangent to the capsule or vertex sphere).
 * Implementations must be safe for concurrent use and allocate nothing per call; points are
 * passed as arrays of length {@link #dimension()} (or more), {@code out} has length at least 3.
 */
public interface Collider {
    /** {@return k, the dimension: 2 or 3} */
    int dimension();

    /** {@return the number of primitives} They are numbered 0 to size() - 1. */
    int size();

    /**
     * The squared distance from {@code p} to primitive {@code i} (0 inside a filled one); the
     * closest point of the primitive goes to {@code out[0..k)} unless {@code out} is null.
     * +infinity for a zero-area triangle or rectangle: like rays, spheres never touch those.
     *
     * @param i   the primitive's index
     * @param p   the point
     * @param out receives the primitive's closest point to {@code p}, or null
     * @return the squared distance from {@code p} to the primitive
     */
    double closestPoint(int i, double[] p, double[] out);

    /**
     * The first contact of a sphere of radius {@code r} whose centre moves along
     * {@code s + t d}: the smallest t in [0, tMax] with {@code distance(s + t d, primitive i) <= r}, or
     * +infinity when there is none. A sphere already touching at t = 0 answers 0; a zero
     * {@code d} answers 0 or +infinity.
     *
     * @param i    the primitive's index
     * @param s    the centre at t = 0
     * @param d    the motion: the centre is at {@code s + d} at t = 1
     * @param r    the radius, at least 0 (0 sweeps a point: a ray)
     * @param tMax the latest t of interest: a query passes its best contact so far
     * @return the first contact's t, or +infinity
     */
    double firstContact(int i, double[] s, double[] d, double r, double tMax);

    /**
     * The primitive's own unit normal, for a contact where the centre lies on the primitive (radius
     * 0, or a start inside), written to {@code out}; false when it has none (a point, a filled
     * 2-D shape, a zero-area triangle). Any of its two orientations.
     *
     * @param i   the primitive's index
     * @param out receives the unit normal
     * @return whether the primitive has a normal (and {@code out} holds it)
     */
    default boolean surfaceNormal(int i, double[] out) {
        return false;
    }
}
