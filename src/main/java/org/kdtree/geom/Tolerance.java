package org.kdtree.geom;

/**
 * The one place for numeric tolerances, passed where needed rather than scattered as
 * literals (after Apache Commons Geometry).
 *
 * <p>Construction needs none: it compares exact coordinates. Tests and ray queries use
 * a relative tolerance scaled by the magnitude of the values they compare.
 *
 * @param relative relative tolerance, e.g. {@code 1e-9}
 * @param absolute absolute floor, for values near zero
 */
public record Tolerance(double relative, double absolute) {
    /** Default for comparing double-precision ray distances. */
    public static final Tolerance DEFAULT = new Tolerance(1e-9, 1e-12);

    /** True when {@code a} and {@code b} agree within this tolerance. */
    public boolean equal(double a, double b) {
        if (a == b) return true;
        double scale = Math.max(Math.abs(a), Math.abs(b));
        return Math.abs(a - b) <= Math.max(absolute, relative * scale);
    }
}
