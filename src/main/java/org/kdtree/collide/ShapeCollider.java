package org.kdtree.collide;

import static org.kdtree.shape.ShapeKind.NEVER;
import static org.kdtree.shape.ShapeKind.POINT;
import static org.kdtree.shape.ShapeKind.RECT;
import static org.kdtree.shape.ShapeKind.SEGMENT;
import static org.kdtree.shape.ShapeKind.TRIANGLE;
import static org.kdtree.shape.ShapeKind.orient;

import org.kdtree.shape.Scene2D;
import org.kdtree.shape.Shape2D;
import org.kdtree.shape.ShapeKind;

/**
 * Circle tests against the 2-D workbench shapes: points, segments, and filled rectangles and
 * triangles. The 3-D feature tests serve with z = 0: a point is hit as a circle around it
 * ({@link SweptPoint}), a segment as a capsule ({@link SweptSegment} for its two long sides, its
 * end points for the round caps). A filled shape is touched at t = 0 when the circle starts on or
 * over it, and otherwise first on its boundary, so its sweep is the earliest over its edges and
 * corners. A zero-area triangle or rectangle is never touched, as a ray never hits it
 * ({@code accel.Shape2DIntersector}'s rule); a zero-length segment is its point.
 */
public final class ShapeCollider implements Collider {
    /** Up to four corners (x, y) per shape, in boundary order; a rectangle's four. */
    private static final int STRIDE = 8;

    private final int[] kind;
    private final double[] xy;

    /**
     * Copies each shape's kind and corners (the shapes are not kept).
     *
     * @param shapes the shapes; primitive i is shape i
     */
    public ShapeCollider(Scene2D shapes) {
        int n = shapes.size();
        kind = new int[n];
        xy = new double[STRIDE * n];
        for (int i = 0; i < n; i++) {
            Shape2D s = shapes.get(i);
            double[] c = s.coords();
            int b = STRIDE * i;
            if (s instanceof Shape2D.Rect r) {
                double[] q = {r.x0(), r.y0(), r.x1(), r.y0(), r.x1(), r.y1(), r.x0(), r.y1()};
                System.arraycopy(q, 0, xy, b, 8);
            } else System.arraycopy(c, 0, xy, b, c.length);
            kind[i] = ShapeKind.of(s);
        }
    }


    @Override public int dimension() { return 2; }
    @Override public int size() { return kind.length; }

    /** +infinity for a zero-area triangle or rectangle (out untouched). */
    @Override public double closestPoint(int i, double[] p, double[] out) {
        int b = STRIDE * i;
        double[] c = xy;
        double x = p[0], y = p[1];
        switch (kind[i]) {
            case POINT -> {
                if (out != null) { out[0] = c[b]; out[1] = c[b + 1]; out[2] = 0; }
                return SweptPoint.distanceSquared(c[b], c[b + 1], 0, x, y, 0);
            }
            case SEGMENT -> {
                return SweptSegment.closestPoint(c[b], c[b + 1], 0, c[b + 2], c[b + 3], 0, x, y, 0, out);
            }
            case RECT -> {
                // Clamping is exact: the closest point of a box.
                double cx = Math.min(Math.max(x, c[b]), c[b + 2]), cy = Math.min(Math.max(y, c[b + 1]), c[b + 5]);
                if (out != null) { out[0] = cx; out[1] = cy; out[2] = 0; }
                return SweptPoint.distanceSquared(cx, cy, 0, x, y, 0);
            }
            case TRIANGLE -> {
                if (insideTriangle(c, b, x, y)) {
                    if (out != null) { out[0] = x; out[1] = y; out[2] = 0; }
                    return 0;
                }
                return closestEdge(c, b, 3, x, y, out);
            }
            default -> {
                return Double.POSITIVE_INFINITY;
            }
        }
    }

    @Override public double firstContact(int i, double[] s, double[] d, double r, double tMax) {
        if (kind[i] == NEVER) return Double.POSITIVE_INFINITY;
        if (closestPoint(i, s, null) <= r * r) return 0;
        int b = STRIDE * i;
        double sx = s[0], sy = s[1], dx = d[0], dy = d[1];
        return switch (kind[i]) {
            case POINT -> SweptPoint.firstContact(xy[b], xy[b + 1], 0, sx, sy, 0, dx, dy, 0, r, tMax);
            case SEGMENT -> Math.min(sweepEdge(b, b + 2, sx, sy, dx, dy, r, tMax),
                    SweptPoint.firstContact(xy[b + 2], xy[b + 3], 0, sx, sy, 0, dx, dy, 0, r, tMax));
            case RECT -> sweepPolygon(b, 4, sx, sy, dx, dy, r, tMax);
            default -> sweepPolygon(b, 3, sx, sy, dx, dy, r, tMax); // a triangle
        };
    }

    @Override public boolean surfaceNormal(int i, double[] out) {
        if (kind[i] != SEGMENT) return false;
        int b = STRIDE * i;
        double ex = xy[b + 2] - xy[b], ey = xy[b + 3] - xy[b + 1], len = Math.sqrt(ex * ex + ey * ey);
        if (len == 0) return false;
        out[0] = -ey / len; out[1] = ex / len; out[2] = 0;
        return true;
    }

    /** The earliest contact over a closed polygon's edges and corners (the start already tested). */
    private double sweepPolygon(int b, int corners, double sx, double sy, double dx, double dy, double r, double tMax) {
        double t = Double.POSITIVE_INFINITY;
        for (int e = 0; e < corners; e++) {
            int p = b + 2 * e, q = b + 2 * ((e + 1) % corners);
            t = Math.min(t, sweepEdge(p, q, sx, sy, dx, dy, r, tMax));
        }
        return t;
    }

    /** One edge's long sides and its first corner (the next edge has the other). */
    private double sweepEdge(int p, int q, double sx, double sy, double dx, double dy, double r, double tMax) {
        double[] c = xy;
        return Math.min(SweptSegment.firstContact(c[p], c[p + 1], 0, c[q], c[q + 1], 0, sx, sy, 0, dx, dy, 0, r, tMax),
                SweptPoint.firstContact(c[p], c[p + 1], 0, sx, sy, 0, dx, dy, 0, r, tMax));
    }

    private static double closestEdge(double[] c, int b, int corners, double x, double y, double[] out) {
        int best = 0;
        double bestD = Double.POSITIVE_INFINITY;
        for (int e = 0; e < corners; e++) {
            int p = b + 2 * e, q = b + 2 * ((e + 1) % corners);
            double d = SweptSegment.closestPoint(c[p], c[p + 1], 0, c[q], c[q + 1], 0, x, y, 0, null);
            if (d < bestD) { bestD = d; best = e; }
        }
        if (out == null) return bestD;
        int p = b + 2 * best, q = b + 2 * ((best + 1) % corners);
        return SweptSegment.closestPoint(c[p], c[p + 1], 0, c[q], c[q + 1], 0, x, y, 0, out);
    }

    /** Closed: a point on an edge is inside. (A zero-area triangle would pass every point of its line.) */
    private static boolean insideTriangle(double[] c, int b, double x, double y) {
        double o1 = orient(c[b], c[b + 1], c[b + 2], c[b + 3], x, y);
        double o2 = orient(c[b + 2], c[b + 3], c[b + 4], c[b + 5], x, y);
        double o3 = orient(c[b + 4], c[b + 5], c[b], c[b + 1], x, y);
        return (o1 >= 0 && o2 >= 0 && o3 >= 0) || (o1 <= 0 && o2 <= 0 && o3 <= 0);
    }

}
