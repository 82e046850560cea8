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
    /**
     * The largest coordinate a triangle mesh may have: the watertight ray/triangle test multiplies
     * up to three coordinates, and beyond 1e100 those products overflow (a ray at 1e110 missed a
     * triangle it hits). Meshes beyond it are refused with a line that says so.
     */
    public static final double MAX_COORDINATE = 1e100;

    /**
     * The smallest extent a triangle mesh may span (unless it is a single point): below 1e-100 the
     * test's products underflow to zero (every hit was reported at t = 0 at 1e-110).
     */
    public static final double MIN_EXTENT = 1e-100;

    /**
     * How much sphere queries ({@code collide}) widen each voxel beyond the radius, relative to the
     * magnitudes involved (scene, centre, motion, radius): 2^-40, thousands of ulps, so that rounding
     * in a plane's t can never prune a voxel the sphere touches. Costs a few extra tests, never a miss.
     */
    public static final double VOXEL_PAD = 0x1p-40;

    /** Default for comparing double-precision ray distances. */
    public static final Tolerance DEFAULT = new Tolerance(1e-9, 1e-12);

    /**
     * True when {@code a} and {@code b} agree within this tolerance.
     *
     * @param a one value
     * @param b the other
     * @return whether they agree
     */
    public boolean equal(double a, double b) {
        if (a == b) return true;
        double scale = Math.max(Math.abs(a), Math.abs(b));
        return Math.abs(a - b) <= Math.max(absolute, relative * scale);
    }
}
