package org.kdtree.collide;

import java.util.Arrays;

/**
 * The result of a swept-sphere query, reused between queries: which primitive the sphere
 * touches first, when (t in [0, 1] along the motion), where its centre is then, the touching
 * point on the primitive, and the contact normal (unit, pointing from the primitive towards the
 * centre). Mutable and owned by the caller, like {@code accel.Hit}.
 */
public final class Contact {
    /** The primitive touched, or -1 for none. */
    public int primitive = -1;
    /** The motion parameter of the first contact; +infinity when there is none. */
    public double t = Double.POSITIVE_INFINITY;
    /** The sphere's centre at the contact. */
    public final double[] centre = new double[3];
    /** The closest point of the primitive to the centre at the contact. */
    public final double[] point = new double[3];
    /**
     * The unit contact normal: from {@link #point} towards {@link #centre}. When they coincide
     * (radius 0, or a sphere starting on or inside a primitive), the primitive's own normal facing
     * against the motion, else the reverse motion direction, else zero.
     */
    public final double[] normal = new double[3];

    /**
     * Forgets any contact.
     *
     * @return this contact
     */
    public Contact reset() {
        primitive = -1;
        t = Double.POSITIVE_INFINITY;
        Arrays.fill(centre, 0);
        Arrays.fill(point, 0);
        Arrays.fill(normal, 0);
        return this;
    }

    /** {@return whether the sphere touches a primitive} */
    public boolean found() { return primitive >= 0; }

    /**
     * Fills centre, point and normal for a contact of primitive {@code p} at {@code t} on the
     * motion {@code s + t d} (called once, after the search).
     */
    void complete(Collider prims, int p, double t, double[] s, double[] d) {
        int k = prims.dimension();
        primitive = p;
        this.t = t;
        for (int a = 0; a < k; a++) centre[a] = t == 0 ? s[a] : s[a] + t * d[a];
        prims.closestPoint(p, centre, point);
        double len = 0, dd = 0;
        for (int a = 0; a < k; a++) {
            normal[a] = centre[a] - point[a];
            len += normal[a] * normal[a];
            dd += d[a] * d[a];
        }
        if (len > 0) { scale(normal, k, 1 / Math.sqrt(len)); return; }
        if (prims.surfaceNormal(p, normal)) {
            double dot = 0;
            for (int a = 0; a < k; a++) dot += normal[a] * d[a];
            if (dot > 0) scale(normal, k, -1);
            return;
        }
        if (dd > 0) {
            for (int a = 0; a < k; a++) normal[a] = d[a];
            scale(normal, k, -1 / Math.sqrt(dd));
        } else Arrays.fill(normal, 0);
    }

    private static void scale(double[] v, int k, double f) {
        for (int a = 0; a < k; a++) v[a] *= f;
    }

    @Override public String toString() {
        return found() ? "Contact[primitive=" + primitive + ", t=" + t + ", centre=" + Arrays.toString(centre)
                + ", point=" + Arrays.toString(point) + ", normal=" + Arrays.toString(normal) + "]" : "Contact[none]";
    }
}
