package org.kdtree.shape;

/**
 * What a 2-D shape is to a ray or a sphere, as an int code for the flat arrays of the hot paths:
 * a point, a segment, a filled rectangle or triangle, or nothing at all when a rectangle or
 * triangle has zero area (no ray hits it and no sphere touches it). The ray traversal's and the
 * collision queries' 2-D tests both decide it here, so they agree on what is there.
 */
public final class ShapeKind {
    /** A point. */
    public static final int POINT = 0;
    /** A segment (a zero-length one is its point). */
    public static final int SEGMENT = 1;
    /** A filled rectangle of positive area. */
    public static final int RECT = 2;
    /** A filled triangle of positive area. */
    public static final int TRIANGLE = 3;
    /** A rectangle or triangle of zero area: never hit, never touched. */
    public static final int NEVER = 4;

    private ShapeKind() {
    }

    /**
     * {@return the kind of {@code s}}
     *
     * @param s a 2-D shape
     */
    public static int of(Shape2D s) {
        if (s instanceof Shape2D.Point) return POINT;
        if (s instanceof Shape2D.Segment) return SEGMENT;
        if (s instanceof Shape2D.Rect r) return r.x0() < r.x1() && r.y0() < r.y1() ? RECT : NEVER;
        double[] c = s.coords();
        return orient(c[0], c[1], c[2], c[3], c[4], c[5]) != 0 ? TRIANGLE : NEVER;
    }

    /**
     * {@return twice the signed area of triangle (a, b, p): positive when p lies left of a -> b}
     *
     * @param ax a's x
     * @param ay a's y
     * @param bx b's x
     * @param by b's y
     * @param px p's x
     * @param py p's y
     */
    public static double orient(double ax, double ay, double bx, double by, double px, double py) {
        return (bx - ax) * (py - ay) - (by - ay) * (px - ax);
    }
}
