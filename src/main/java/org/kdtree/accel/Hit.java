package org.kdtree.accel;

/**
 * The result of a ray query, reused between rays: the primitive hit, the ray parameter t, and
 * the hit's barycentric coordinates (u, v) on a triangle (w = 1 - u - v belongs to the first
 * vertex) or the segment parameter in 2-D.
 */
public final class Hit {
    /** The primitive hit, or -1 for none. */
    public int primitive = -1;
    /** The ray parameter of the hit; +infinity when there is none. */
    public double t = Double.POSITIVE_INFINITY;
    /** Barycentric coordinates of the hit on a triangle (u for vertex 1, v for vertex 2). */
    public double u, v;

    /**
     * Forgets any hit.
     *
     * @return this hit
     */
    public Hit reset() {
        primitive = -1;
        t = Double.POSITIVE_INFINITY;
        u = v = 0;
        return this;
    }

    /** {@return whether a primitive was hit} */
    public boolean found() { return primitive >= 0; }

    @Override public String toString() {
        return found() ? "Hit[primitive=" + primitive + ", t=" + t + ", u=" + u + ", v=" + v + "]" : "Hit[none]";
    }
}
