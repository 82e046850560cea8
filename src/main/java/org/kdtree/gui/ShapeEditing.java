package org.kdtree.gui;

import java.awt.geom.Point2D;
import java.util.List;
import org.kdtree.shape.Shape2D;

/** Mouse editing of 2-D shapes: picking, moving whole shapes, dragging one corner. */
final class ShapeEditing {
    private ShapeEditing() {
    }

    /**
     * The topmost shape at (x, y) within {@code tol} (scene units), or -1.
     *
     * @param shapes the scene's shapes
     * @param x the point's x
     * @param y the point's y
     * @param tol the distance allowed, in scene units
     * @return the index of the shape
     */
    public static int pick(List<Shape2D> shapes, double x, double y, double tol) {
        for (int i = shapes.size() - 1; i >= 0; i--) if (contains(shapes.get(i), x, y, tol)) return i;
        return -1;
    }

    static boolean contains(Shape2D s, double x, double y, double tol) {
        double[] c = s.coords();
        if (s instanceof Shape2D.Point) return Point2D.distance(c[0], c[1], x, y) <= tol;
        if (s instanceof Shape2D.Segment) return java.awt.geom.Line2D.ptSegDist(c[0], c[1], c[2], c[3], x, y) <= tol;
        if (s instanceof Shape2D.Rect) return x >= c[0] - tol && x <= c[2] + tol && y >= c[1] - tol && y <= c[3] + tol;
        java.awt.geom.Path2D.Double p = new java.awt.geom.Path2D.Double();
        p.moveTo(c[0], c[1]);
        p.lineTo(c[2], c[3]);
        p.lineTo(c[4], c[5]);
        p.closePath();
        return p.contains(x, y) || vertexNear(s, x, y, tol) >= 0;
    }

    /**
     * {@return the corners a user can drag}, as {x, y} pairs: a rectangle has four, the other shapes their own points.
     *
     * @param s the shape
     */
    public static double[] handles(Shape2D s) {
        double[] c = s.coords();
        if (s instanceof Shape2D.Rect) return new double[] {c[0], c[1], c[2], c[1], c[2], c[3], c[0], c[3]};
        return c;
    }

    /**
     * {@return the handle of {@code s} within {@code tol} of (x, y), or -1}
     *
     * @param s the shape
     * @param x the point's x
     * @param y the point's y
     * @param tol the distance allowed, in scene units
     */
    public static int vertexNear(Shape2D s, double x, double y, double tol) {
        double[] h = handles(s);
        for (int k = 0; k < h.length / 2; k++) if (Point2D.distance(h[2 * k], h[2 * k + 1], x, y) <= tol) return k;
        return -1;
    }

    /**
     * {@return {@code s} moved by (dx, dy)}
     *
     * @param s the shape
     * @param dx the move along x
     * @param dy the move along y
     */
    public static Shape2D translate(Shape2D s, double dx, double dy) {
        double[] c = s.coords();
        for (int i = 0; i < c.length; i++) c[i] += i % 2 == 0 ? dx : dy;
        return make(s, c);
    }

    /**
     * {@return {@code s} with handle {@code k} moved to (x, y)}; a rectangle keeps the opposite corner.
     *
     * @param s the shape
     * @param k the handle's index in {@link #handles}
     * @param x the new x
     * @param y the new y
     */
    public static Shape2D moveHandle(Shape2D s, int k, double x, double y) {
        if (s instanceof Shape2D.Rect) {
            double[] h = handles(s);
            int opp = (k + 2) % 4;
            return new Shape2D.Rect(h[2 * opp], h[2 * opp + 1], x, y);
        }
        double[] c = s.coords();
        c[2 * k] = x;
        c[2 * k + 1] = y;
        return make(s, c);
    }

    /** A shape of the same kind as {@code like} with coordinates {@code c}. */
    static Shape2D make(Shape2D like, double[] c) {
        if (like instanceof Shape2D.Point) return new Shape2D.Point(c[0], c[1]);
        if (like instanceof Shape2D.Segment) return new Shape2D.Segment(c[0], c[1], c[2], c[3]);
        if (like instanceof Shape2D.Rect) return new Shape2D.Rect(c[0], c[1], c[2], c[3]);
        return new Shape2D.Triangle(c[0], c[1], c[2], c[3], c[4], c[5]);
    }

    /**
     * {@return the shape a drag from (x0, y0) to (x1, y1) adds with {@code tool}, or null} for a tool that adds nothing.
     *
     * @param tool the edit tool
     * @param x0 the drag's start x
     * @param y0 the drag's start y
     * @param x1 the drag's end x
     * @param y1 the drag's end y
     */
    public static Shape2D created(EditTool tool, double x0, double y0, double x1, double y1) {
        return switch (tool) {
            case POINT -> new Shape2D.Point(x1, y1);
            case SEGMENT -> new Shape2D.Segment(x0, y0, x1, y1);
            case RECT -> new Shape2D.Rect(x0, y0, x1, y1);
            case TRIANGLE -> {
                double mx = 0.5 * (x0 + x1), my = 0.5 * (y0 + y1);
                double len = Math.hypot(x1 - x0, y1 - y0);
                double nx = len == 0 ? 0 : -(y1 - y0) / len, ny = len == 0 ? 1 : (x1 - x0) / len;
                double h = 0.8 * len;
                yield new Shape2D.Triangle(x0, y0, x1, y1, mx + h * nx, my + h * ny);
            }
            default -> null;
        };
    }
}
