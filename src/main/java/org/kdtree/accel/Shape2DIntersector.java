package org.kdtree.accel;

import static org.kdtree.shape.ShapeKind.NEVER;
import static org.kdtree.shape.ShapeKind.POINT;
import static org.kdtree.shape.ShapeKind.RECT;
import static org.kdtree.shape.ShapeKind.SEGMENT;
import static org.kdtree.shape.ShapeKind.TRIANGLE;
import static org.kdtree.shape.ShapeKind.orient;

import org.kdtree.geom.Ray;
import org.kdtree.shape.Scene2D;
import org.kdtree.shape.Shape2D;
import org.kdtree.shape.ShapeKind;

/**
 * Exact ray tests for the 2-D workbench shapes: segments, filled rectangles, filled
 * triangles, and points.
 *
 * <p>Every test rests on one orientation sign per vertex, {@code side(P) = cross(d, P - o)}:
 * a ray meets a segment when its two ends are not strictly on the same side. A vertex shared
 * by two segments has one side value for both, so no ray slips between them (the 2-D analogue
 * of the watertight triangle test); a ray through an end point, or along a segment, hits it.
 * A filled shape is hit at {@code tMin} when the ray starts inside it (closed: the boundary
 * counts), otherwise at its closest boundary edge. A point is hit only when it lies exactly on
 * the ray. Zero-area rectangles and triangles are never hit.
 *
 * <p>{@code Hit.u} is the parameter along a hit segment or edge (0 at its first end); for a hit
 * from inside, u and v are 0.
 */
final class Shape2DIntersector implements Intersector {

    private final int[] kind;
    /** Up to three vertices (x, y) per shape; rectangles store their two corners. */
    private final double[] xy;

    /**
     * An intersector for the shapes, with their vertices copied into flat arrays.
     *
     * @param shapes the 2-D scene
     */
    public Shape2DIntersector(Scene2D shapes) {
        int n = shapes.size();
        kind = new int[n];
        xy = new double[6 * n];
        for (int i = 0; i < n; i++) {
            Shape2D s = shapes.get(i);
            double[] c = s.coords();
            System.arraycopy(c, 0, xy, 6 * i, c.length);
            kind[i] = ShapeKind.of(s);
        }
    }


    @Override public int dimension() { return 2; }
    @Override public int size() { return kind.length; }

    @Override public boolean intersect(int i, Ray ray, double tMin, double tMax, Hit hit) {
        double limit = tMax;
        int b = 6 * i;
        double[] p = xy;
        return switch (kind[i]) {
            case POINT -> point(i, p[b], p[b + 1], ray, tMin, limit, hit);
            case SEGMENT -> segment(i, p[b], p[b + 1], p[b + 2], p[b + 3], ray, tMin, limit, hit);
            case RECT -> rect(i, p[b], p[b + 1], p[b + 2], p[b + 3], ray, tMin, limit, hit);
            case TRIANGLE -> triangle(i, b, ray, tMin, limit, hit);
            default -> false;
        };
    }

    private static boolean point(int i, double px, double py, Ray r, double tMin, double limit, Hit hit) {
        double dx = r.direction(0), dy = r.direction(1);
        double qx = px - r.origin(0), qy = py - r.origin(1);
        if (dx * qy - dy * qx != 0) return false;
        double t = (qx * dx + qy * dy) / (dx * dx + dy * dy);
        return record(i, t, 0, tMin, limit, hit);
    }

    private static boolean segment(int i, double x0, double y0, double x1, double y1, Ray r, double tMin,
                                   double limit, Hit hit) {
        double dx = r.direction(0), dy = r.direction(1), ox = r.origin(0), oy = r.origin(1);
        double s0 = dx * (y0 - oy) - dy * (x0 - ox);
        double s1 = dx * (y1 - oy) - dy * (x1 - ox);
        if ((s0 > 0 && s1 > 0) || (s0 < 0 && s1 < 0)) return false;
        if (s0 == 0 && s1 == 0) return collinear(i, x0, y0, x1, y1, r, tMin, limit, hit);
        // t as a convex combination of the ends' ray parameters (as Woop et al. do for depth): it
        // stays between them however close to parallel the ray and the segment are.
        double lambda = s0 / (s0 - s1), dd = dx * dx + dy * dy;
        double t0 = ((x0 - ox) * dx + (y0 - oy) * dy) / dd, t1 = ((x1 - ox) * dx + (y1 - oy) * dy) / dd;
        double t = lambda == 1 ? t1 : t0 + lambda * (t1 - t0);
        return record(i, t, lambda, tMin, limit, hit);
    }

    /** A ray along the segment's line: hit where it first meets the segment at or after tMin. */
    private static boolean collinear(int i, double x0, double y0, double x1, double y1, Ray r, double tMin,
                                     double limit, Hit hit) {
        double dx = r.direction(0), dy = r.direction(1), dd = dx * dx + dy * dy;
        double t0 = ((x0 - r.origin(0)) * dx + (y0 - r.origin(1)) * dy) / dd;
        double t1 = ((x1 - r.origin(0)) * dx + (y1 - r.origin(1)) * dy) / dd;
        double lo = Math.min(t0, t1), hi = Math.max(t0, t1);
        if (hi < tMin) return false;
        double t = Math.max(lo, tMin);
        double lambda = t1 == t0 ? 0 : (t - t0) / (t1 - t0);
        return record(i, t, lambda, tMin, limit, hit);
    }

    private static boolean rect(int i, double x0, double y0, double x1, double y1, Ray r, double tMin,
                                double limit, Hit hit) {
        double px = r.at(tMin, 0), py = r.at(tMin, 1);
        if (px >= x0 && px <= x1 && py >= y0 && py <= y1) return inside(i, tMin, limit, hit);
        return closestEdge(i, x0, y0, x1, y0, x1, y1, x0, y1, r, tMin, limit, hit);
    }

    private boolean triangle(int i, int b, Ray r, double tMin, double limit, Hit hit) {
        double[] p = xy;
        double px = r.at(tMin, 0), py = r.at(tMin, 1);
        double o1 = orient(p[b], p[b + 1], p[b + 2], p[b + 3], px, py);
        double o2 = orient(p[b + 2], p[b + 3], p[b + 4], p[b + 5], px, py);
        double o3 = orient(p[b + 4], p[b + 5], p[b], p[b + 1], px, py);
        boolean in = (o1 >= 0 && o2 >= 0 && o3 >= 0) || (o1 <= 0 && o2 <= 0 && o3 <= 0);
        if (in) return inside(i, tMin, limit, hit);
        return closestEdge(i, p[b], p[b + 1], p[b + 2], p[b + 3], p[b + 4], p[b + 5], Double.NaN, Double.NaN,
                r, tMin, limit, hit);
    }

    /** The closest hit on the closed polygon a-b-c(-d) (d NaN for a triangle). */
    private static boolean closestEdge(int i, double ax, double ay, double bx, double by,
                                       double cx, double cy, double dx, double dy, Ray r, double tMin,
                                       double limit, Hit hit) {
        boolean quad = !Double.isNaN(dx);
        boolean found = segment(i, ax, ay, bx, by, r, tMin, limit, hit);
        found |= segment(i, bx, by, cx, cy, r, tMin, limit, hit);
        if (quad) {
            found |= segment(i, cx, cy, dx, dy, r, tMin, limit, hit);
            found |= segment(i, dx, dy, ax, ay, r, tMin, limit, hit);
        } else {
            found |= segment(i, cx, cy, ax, ay, r, tMin, limit, hit);
        }
        return found;
    }

    private static boolean inside(int i, double tMin, double limit, Hit hit) {
        if (!(tMin <= limit && tMin < hit.t)) return false;
        hit.primitive = i;
        hit.t = tMin;
        hit.u = hit.v = 0;
        return true;
    }

    private static boolean record(int i, double t, double u, double tMin, double limit, Hit hit) {
        if (!(t >= tMin && t <= limit && t < hit.t)) return false;
        hit.primitive = i;
        hit.t = t;
        hit.u = u;
        hit.v = 0;
        return true;
    }

}
