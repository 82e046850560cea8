package org.kdtree.shape;

import org.kdtree.geom.Box;
import org.kdtree.geom.PolygonClipper;

/** One object of a 2-D workbench scene: a point, a segment, a rectangle or a triangle. */
public sealed interface Shape2D permits Shape2D.Point, Shape2D.Segment, Shape2D.Rect, Shape2D.Triangle {

    /**
     * Writes this shape's bounds into a 2-D {@code dest}.
     *
     * @param dest a 2-D box
     */
    void bounds(Box dest);

    /**
     * Writes the bounds of the part inside {@code voxel} into {@code dest} (empty if none).
     *
     * @param voxel the voxel to clip to
     * @param dest receives the bounds
     */
    void clip(Box voxel, Box dest);

    /** {@return the coordinates, in the order of the scene file format} */
    double[] coords();

    /** {@return the keyword of the scene file format: point, segment, rect, triangle} */
    String keyword();

    /** A point (x, y). */
    record Point(double x, double y) implements Shape2D {
        public void bounds(Box d) { d.setMin(0, x).setMax(0, x).setMin(1, y).setMax(1, y); }
        public void clip(Box v, Box d) {
            if (v.contains(new double[] {x, y})) bounds(d); else d.setEmpty();
        }
        public double[] coords() { return new double[] {x, y}; }
        public String keyword() { return "point"; }
    }

    /** A segment from (x0, y0) to (x1, y1). */
    record Segment(double x0, double y0, double x1, double y1) implements Shape2D {
        public void bounds(Box d) {
            d.setMin(0, Math.min(x0, x1)).setMax(0, Math.max(x0, x1));
            d.setMin(1, Math.min(y0, y1)).setMax(1, Math.max(y0, y1));
        }
        public void clip(Box v, Box d) { PolygonClipper.forThread(2).clip(coords(), 2, v, d); }
        public double[] coords() { return new double[] {x0, y0, x1, y1}; }
        public String keyword() { return "segment"; }
    }

    /** An axis-aligned rectangle, filled, with corners (x0, y0) and (x1, y1) in any order. */
    record Rect(double x0, double y0, double x1, double y1) implements Shape2D {
        /**
         * Orders the corners so that (x0, y0) is the lower left one.
         *
         * @param x0 x of one corner
         * @param y0 y of one corner
         * @param x1 x of the opposite corner
         * @param y1 y of the opposite corner
         */
        public Rect {
            double ax = Math.min(x0, x1), bx = Math.max(x0, x1);
            double ay = Math.min(y0, y1), by = Math.max(y0, y1);
            x0 = ax; x1 = bx; y0 = ay; y1 = by;
        }
        public void bounds(Box d) { d.setMin(0, x0).setMax(0, x1).setMin(1, y0).setMax(1, y1); }
        public void clip(Box v, Box d) {
            bounds(d);
            d.intersect(v);
            if (d.isEmpty()) d.setEmpty();
        }
        public double[] coords() { return new double[] {x0, y0, x1, y1}; }
        public String keyword() { return "rect"; }
    }

    /** A filled triangle with vertices a, b, c. */
    record Triangle(double ax, double ay, double bx, double by, double cx, double cy) implements Shape2D {
        public void bounds(Box d) {
            d.setMin(0, Math.min(ax, Math.min(bx, cx))).setMax(0, Math.max(ax, Math.max(bx, cx)));
            d.setMin(1, Math.min(ay, Math.min(by, cy))).setMax(1, Math.max(ay, Math.max(by, cy)));
        }
        public void clip(Box v, Box d) { PolygonClipper.forThread(2).clip(coords(), 3, v, d); }
        public double[] coords() { return new double[] {ax, ay, bx, by, cx, cy}; }
        public String keyword() { return "triangle"; }
    }
}
