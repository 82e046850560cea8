package org.kdtree.geom;

/**
 * The split plane {@code p(n, xi): x_n = xi} of the talk, with the side that receives
 * primitives lying exactly in the plane ("planar" primitives, chosen by the SAH).
 *
 * @param axis       n, the axis normal to the plane, in {@code [0, k)}
 * @param position   xi, the plane's coordinate on that axis
 * @param planarLeft true when planar primitives go to the left (lower) child
 */
public record SplitPlane(int axis, double position, boolean planarLeft) {
    /**
     * A plane whose planar primitives go left, the convention of the simple builders.
     *
     * @param axis n, the axis normal to the plane
     * @param position xi, the plane's coordinate on that axis
     */
    public SplitPlane(int axis, double position) {
        this(axis, position, true);
    }

    /**
     * Checks the plane.
     *
     * @param axis n, the axis normal to the plane, in {@code [0, k)}
     * @param position xi, the plane's coordinate on that axis
     * @param planarLeft true when planar primitives go to the left (lower) child
     * @throws IllegalArgumentException for a negative axis or a non-finite position
     */
    public SplitPlane {
        if (axis < 0) throw new IllegalArgumentException("axis must be >= 0, got " + axis);
        if (!Double.isFinite(position))
            throw new IllegalArgumentException("split position must be finite, got " + position);
    }
}
