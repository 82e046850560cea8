package org.kdtree.geom;

/**
 * Clips a convex polygon (a triangle, a segment, or a degenerate polygon) to a box and
 * returns the bounds of the part inside: the "perfect split" bounds of Wald and Havran.
 *
 * <p>Sutherland-Hodgman against the 2k faces of the box. The result is conservative: a
 * vertex created on a face gets that face's coordinate exactly, and every bound is padded
 * outward by a few units in the last place of the primitive's coordinates, then intersected
 * with the primitive's own bounds and the box. So a bound never lies inside the true part,
 * and a bound that equals a vertex coordinate or a face of the box is exact.
 *
 * <p>Instances hold scratch buffers and are not thread-safe; {@link #forThread(int)} gives
 * each thread its own.
 */
public final class PolygonClipper {
    /** Relative padding of computed coordinates ({@link Tolerance#CLIP_PAD}). */
    static final double PAD = Tolerance.CLIP_PAD;
    private static final ThreadLocal<PolygonClipper[]> PER_THREAD =
            ThreadLocal.withInitial(() -> new PolygonClipper[8]);

    private final int k;
    private double[] a, b;

    /**
     * A clipper for polygons in {@code k} dimensions, with its own scratch buffers.
     *
     * @param k the dimension
     */
    public PolygonClipper(int k) {
        this.k = k;
        int cap = (4 + 2 * k) * k;
        a = new double[cap];
        b = new double[cap];
    }

    /**
     * This thread's clipper for dimension {@code k}.
     *
     * @param k the dimension
     * @return the calling thread's clipper, made on first use
     */
    public static PolygonClipper forThread(int k) {
        PolygonClipper[] cache = PER_THREAD.get();
        if (k < cache.length) {
            if (cache[k] == null) cache[k] = new PolygonClipper(k);
            return cache[k];
        }
        return new PolygonClipper(k);
    }

    /**
     * Bounds of the part of the polygon inside {@code box}.
     *
     * @param verts  the vertices, k coordinates each, {@code n} of them, in order
     * @param n      the number of vertices (2 for a segment, 3 for a triangle)
     * @param box    the clipping box (a voxel)
     * @param dest   receives the bounds; set empty when the polygon misses the box
     * @return dest
     */
    public Box clip(double[] verts, int n, Box box, Box dest) {
        ensure(n);
        System.arraycopy(verts, 0, a, 0, n * k);
        int count = n;
        for (int axis = 0; axis < k && count > 0; axis++) {
            count = clipHalf(count, axis, box.min(axis), true);
            count = clipHalf(count, axis, box.max(axis), false);
        }
        dest.setEmpty();
        if (count == 0) return dest;
        for (int i = 0; i < count; i++) dest.grow(a, i * k);
        padAndClamp(verts, n, box, dest);
        return dest;
    }

    /** Keeps the part with {@code x_axis >= plane} (lower face) or {@code <= plane}; result in a. */
    private int clipHalf(int count, int axis, double plane, boolean keepAbove) {
        if (allInside(count, axis, plane, keepAbove)) return count;   // the pass would copy a unchanged
        int out = 0;
        for (int i = 0; i < count; i++) {
            int p = i * k, q = ((i + 1) % count) * k;
            double dp = keepAbove ? a[p + axis] - plane : plane - a[p + axis];
            double dq = keepAbove ? a[q + axis] - plane : plane - a[q + axis];
            boolean inP = dp >= 0, inQ = dq >= 0;
            if (inP) out = emit(a, p, out);
            if (inP != inQ && count > 1) {
                double t = dp / (dp - dq);
                int o = out * k;
                for (int c = 0; c < k; c++) b[o + c] = a[p + c] + t * (a[q + c] - a[p + c]);
                b[o + axis] = plane;
                out++;
            }
        }
        double[] tmp = a; a = b; b = tmp;
        return out;
    }

    private boolean allInside(int count, int axis, double plane, boolean keepAbove) {
        for (int i = 0; i < count; i++) {
            double d = keepAbove ? a[i * k + axis] - plane : plane - a[i * k + axis];
            if (!(d >= 0)) return false;
        }
        return true;
    }

    private int emit(double[] src, int at, int out) {
        System.arraycopy(src, at, b, out * k, k);
        return out + 1;
    }

    /** Pads computed bounds outward, then intersects with the primitive's bounds and the box. */
    private void padAndClamp(double[] verts, int n, Box box, Box dest) {
        for (int axis = 0; axis < k; axis++) {
            double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY, scale = 0;
            for (int i = 0; i < n; i++) {
                double v = verts[i * k + axis];
                lo = Math.min(lo, v);
                hi = Math.max(hi, v);
                scale = Math.max(scale, Math.abs(v));
            }
            double pad = PAD * scale + Double.MIN_NORMAL;
            double min = Math.max(Math.max(dest.min(axis) - pad, lo), box.min(axis));
            double max = Math.min(Math.min(dest.max(axis) + pad, hi), box.max(axis));
            dest.setMin(axis, min).setMax(axis, max);
        }
    }

    private void ensure(int n) {
        int cap = (n + 2 * k + 2) * k;
        if (a.length < cap) {
            a = new double[cap];
            b = new double[cap];
        }
    }
}
