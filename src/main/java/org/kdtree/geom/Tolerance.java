package org.kdtree.geom;

/**
 * The one place for numeric tolerances, passed where needed rather than scattered as
 * literals (after Apache Commons Geometry): each constant below is the one the code uses, with
 * the reason for its value.
 *
 * <p>The SAH's plane choice needs none: it compares exact coordinates. Clipping pads its
 * results, the traversal and the point and sphere queries allow a relative slack so that
 * rounding never loses an answer, and tests compare with an instance of this record. No other
 * main class writes a tolerance as a literal (a test reads the sources to keep it so); the
 * traversal's slack is here too, {@link #TRAVERSAL_SLACK}. Thresholds that are not about rounding
 * stay with their users: the tracer's {@code EffectPlan.NEGLIGIBLE_WEIGHT} (an invisible path
 * weight), the workbench's zoom limits.
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

    /**
     * Relative slack on the ray traversal's interval comparisons (tMin, tMax against tSplit):
     * 2^-46, a few hundred ulps, far above the rounding of tSplit, so that a ray through a
     * split plane or a voxel's corner never skips the voxel holding its hit.
     */
    public static final double TRAVERSAL_SLACK = 0x1p-46;

    /**
     * Relative slack on point queries' pruning: a voxel whose computed distance exceeds the bound
     * by less than this is still visited. Incremental sums round differently from a point's own
     * sum, and a point on a voxel's face at exactly the k-th distance (a tie, common on grid data)
     * must not be lost to an ulp. It costs at most a few extra voxels.
     */
    public static final double PRUNE_SLACK = 1e-10;

    /**
     * Relative padding of clipped coordinates: about 4.5 units in the last place, so that the
     * clipped bounds of a primitive are never smaller than its exact part inside the voxel.
     */
    public static final double CLIP_PAD = 1e-15;

    /**
     * How far, relatively, a student's expected SAH cost may exceed the median plane's and still
     * count as "at most" in the contract's quality tier: rounding in the two sums, not a margin.
     */
    public static final double COST_SLACK = 1e-9;

    /**
     * The builder contract's margin, relative to the scene's size (or the root's measure), when it
     * compares sample points with voxels and sums the leaves' measures: rounding in those sums and
     * in the sample points must never raise a false alarm; a real fault is far larger.
     */
    public static final double CHECK_MARGIN = 1e-9;

    /**
     * Relative growth of a box before a primitive is tested against it (twice {@link #CLIP_PAD},
     * about 8 ulps), so that bounds computed by two roundings still meet.
     */
    public static final double BOX_PAD = 2e-15;

    /**
     * Relative offset of a secondary ray's origin from the surface it leaves (doubles round at
     * about 1e-16 relative): no self-intersection at any scale, and no visible gap either.
     */
    public static final double RAY_OFFSET = 1e-9;

    /**
     * Relative margin by which a box of points must lie off a triangle's plane for a packet of
     * segments between such boxes to skip the triangle (the BVH's any-hit packets): the plane's
     * normal and the sums round at about 1e-16 relative, the watertight test's t likewise, so a
     * margin of a billion ulps leaves no case where the test would have found a hit.
     */
    public static final double PLANE_SIDE_MARGIN = 1e-7;

    /**
     * How far short of a point light a shadow ray stops, relative to its length, so that the
     * light's own panel does not occlude it.
     */
    public static final double SHADOW_SHORTFALL = 1e-7;

    /**
     * Below this many ulps of the coordinates' square (times 4), a triangle's double-precision
     * cross product cannot tell a degenerate triangle from a thin one; exact arithmetic decides.
     */
    public static final double DEGENERATE_ULPS = 64;

    /**
     * The smallest sine of the angle between a camera's up hint and its view direction: below it
     * their cross product (the image's right-hand axis) is mostly rounding, and the picture would
     * spin with the last bits of the input, so the scene file refuses such a camera.
     */
    public static final double PARALLEL_SINE = 1e-9;

    /**
     * How far a ball stopped at a contact is set off the surface, relative to the scene's extent:
     * far above the rounding of the contact point (about 1e-16 relative), so that its next sweep
     * does not start inside the surface, and far below anything visible.
     */
    public static final double CONTACT_SKIN = 1e-9;

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
