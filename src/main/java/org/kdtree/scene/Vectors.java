package org.kdtree.scene;

/**
 * Operations on 3-vectors held in {@code double[3]} arrays, for the tracer's per-ray code, which
 * must not allocate. Each computes in the same order as the {@link Vec3} operation of the same
 * name, so the two agree to the last bit (renders are compared bit for bit).
 */
public final class Vectors {
    private Vectors() {
    }

    /**
     * {@return a · b}, summed x, y, z in that order
     *
     * @param a one vector
     * @param b the other
     */
    public static double dot(double[] a, double[] b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    /**
     * Scales {@code a} to unit length in place (multiplying by the reciprocal of its length); leaves zero alone.
     *
     * @param a the vector
     */
    public static void normalize(double[] a) {
        double l = Math.sqrt(dot(a, a));
        if (l > 0) scale(a, 1 / l);
    }

    /**
     * Multiplies {@code a} by {@code s} in place.
     *
     * @param a the vector
     * @param s the factor
     */
    public static void scale(double[] a, double s) {
        a[0] *= s;
        a[1] *= s;
        a[2] *= s;
    }

    /**
     * Negates {@code a} in place.
     *
     * @param a the vector
     */
    public static void negate(double[] a) {
        a[0] = -a[0];
        a[1] = -a[1];
        a[2] = -a[2];
    }

    /**
     * Copies {@code v} into {@code out}.
     *
     * @param v the vector
     * @param out receives its components
     * @return {@code out}
     */
    public static double[] set(Vec3 v, double[] out) {
        out[0] = v.x();
        out[1] = v.y();
        out[2] = v.z();
        return out;
    }

    /**
     * Writes the mirror image of {@code d} about unit {@code n}, d - 2 (d · n) n, to {@code out} (not {@code d} or {@code n}).
     *
     * @param d the incoming direction
     * @param n the unit normal
     * @param out receives the reflected direction
     */
    public static void reflect(double[] d, double[] n, double[] out) {
        double k = 2 * dot(d, n);
        out[0] = d[0] - n[0] * k;
        out[1] = d[1] - n[1] * k;
        out[2] = d[2] - n[2] * k;
    }

    /**
     * {@return the largest absolute component}: the magnitude that rounding errors scale with.
     *
     * @param a the vector
     */
    public static double maxAbs(double[] a) {
        return Math.max(Math.abs(a[0]), Math.max(Math.abs(a[1]), Math.abs(a[2])));
    }

    /**
     * {@return the largest component} (path weights).
     *
     * @param a the vector
     */
    public static double max(double[] a) {
        return Math.max(a[0], Math.max(a[1], a[2]));
    }
}
