package org.kdtree.geom;

/**
 * {@link PolygonClipper} specialised to one 3-D triangle: the same Sutherland-Hodgman passes in
 * the same order with the same arithmetic, so the bounds are bit for bit the same, but written
 * for three coordinates in flat scratch arrays, without {@code Box} updates in the loop and
 * without the generic clipper's modulo and per-vertex copies. The SAH builds clip every
 * straddling triangle twice per split, so this is on their hot path.
 *
 * <p>Instances hold scratch buffers and are not thread-safe; {@link #forThread()} gives each
 * thread its own.
 */
public final class TriangleClipper {
    /** A triangle clipped by six planes has at most 3 + 6 vertices. */
    private static final int MAX_VERTICES = 9;
    private static final ThreadLocal<TriangleClipper> PER_THREAD = ThreadLocal.withInitial(TriangleClipper::new);

    private final double[] a = new double[3 * MAX_VERTICES];
    private final double[] b = new double[3 * MAX_VERTICES];

    /** This thread's clipper. */
    public static TriangleClipper forThread() {
        return PER_THREAD.get();
    }

    /**
     * Bounds of the part inside {@code box} of the triangle whose corners are the points
     * {@code i0, i1, i2} (indices of x, y, z triples) of {@code vertices}; {@code dest} is set
     * empty when the triangle misses the box. Same result as {@link PolygonClipper#clipTriangle}.
     */
    public Box clip(double[] vertices, int i0, int i1, int i2, Box box, Box dest) {
        double[] src = a, dst = b;
        int p0 = 3 * i0, p1 = 3 * i1, p2 = 3 * i2;
        src[0] = vertices[p0]; src[1] = vertices[p0 + 1]; src[2] = vertices[p0 + 2];
        src[3] = vertices[p1]; src[4] = vertices[p1 + 1]; src[5] = vertices[p1 + 2];
        src[6] = vertices[p2]; src[7] = vertices[p2 + 1]; src[8] = vertices[p2 + 2];
        int count = 3;
        for (int pass = 0; pass < 6 && count > 0; pass++) {
            int axis = pass >> 1;
            boolean keepAbove = (pass & 1) == 0;   // the lower face keeps x >= min, the upper x <= max
            double plane = keepAbove ? box.min(axis) : box.max(axis);
            if (allInside(src, count, axis, plane, keepAbove)) continue;   // the pass would copy src unchanged
            count = clipHalf(src, dst, count, axis, plane, keepAbove);
            double[] t = src; src = dst; dst = t;
        }
        if (count == 0) return dest.setEmpty();
        for (int axis = 0; axis < 3; axis++) bound(src, vertices, p0, p1, p2, count, axis, box, dest);
        return dest;
    }

    /** The axis's bounds of the clipped polygon, padded and clamped as PolygonClipper does. */
    private static void bound(double[] polygon, double[] vertices, int p0, int p1, int p2, int count, int axis,
                              Box box, Box dest) {
        double min = Double.POSITIVE_INFINITY, max = Double.NEGATIVE_INFINITY;
        for (int i = axis; i < 3 * count; i += 3) {
            double v = polygon[i];
            if (v < min) min = v;
            if (v > max) max = v;
        }
        double v0 = vertices[p0 + axis], v1 = vertices[p1 + axis], v2 = vertices[p2 + axis];
        double lo = Math.min(Math.min(Math.min(Double.POSITIVE_INFINITY, v0), v1), v2);
        double hi = Math.max(Math.max(Math.max(Double.NEGATIVE_INFINITY, v0), v1), v2);
        double scale = Math.max(Math.max(Math.max(0, Math.abs(v0)), Math.abs(v1)), Math.abs(v2));
        double pad = PolygonClipper.PAD * scale + Double.MIN_NORMAL;
        dest.setMin(axis, Math.max(Math.max(min - pad, lo), box.min(axis)));
        dest.setMax(axis, Math.min(Math.min(max + pad, hi), box.max(axis)));
    }

    private static boolean allInside(double[] polygon, int count, int axis, double plane, boolean keepAbove) {
        for (int i = axis; i < 3 * count; i += 3)
            if (!(distance(polygon[i], plane, keepAbove) >= 0)) return false;
        return true;
    }

    /** Writes the part of {@code src} with {@code x_axis >= plane} (keepAbove) or {@code <= plane} to {@code dst}. */
    private static int clipHalf(double[] src, double[] dst, int count, int axis, double plane, boolean keepAbove) {
        int out = 0;
        for (int i = 0; i < count; i++) {
            int p = 3 * i, q = i + 1 == count ? 0 : p + 3;
            double dp = distance(src[p + axis], plane, keepAbove), dq = distance(src[q + axis], plane, keepAbove);
            boolean inP = dp >= 0;
            if (inP) {
                dst[3 * out] = src[p];
                dst[3 * out + 1] = src[p + 1];
                dst[3 * out + 2] = src[p + 2];
                out++;
            }
            if (inP != (dq >= 0) && count > 1) {
                double t = dp / (dp - dq);
                int o = 3 * out;
                dst[o] = src[p] + t * (src[q] - src[p]);
                dst[o + 1] = src[p + 1] + t * (src[q + 1] - src[p + 1]);
                dst[o + 2] = src[p + 2] + t * (src[q + 2] - src[p + 2]);
                dst[o + axis] = plane;
                out++;
            }
        }
        return out;
    }

    /** Signed distance to the plane, positive on the kept side (the generic clipper's expression). */
    private static double distance(double x, double plane, boolean keepAbove) {
        return keepAbove ? x - plane : plane - x;
    }
}
