package org.kdtree.geom;

/**
 * {@link PolygonClipper} specialised to one 3-D triangle: the same Sutherland-Hodgman passes in
 * the same order with the same arithmetic, so {@link #clip} gives bit for bit the same bounds,
 * but written for three coordinates in flat scratch arrays, without {@code Box} updates in the
 * loop and without the generic clipper's modulo and per-vertex copies.
 *
 * <p>The SAH builds clip every straddling triangle to both children of a split: {@link #clipSplit}
 * clips it to the parent voxel once and cuts that polygon by the split plane, instead of
 * clipping it twice from scratch.
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
    /** The signed distances of the polygon's vertices to the plane of the current pass. */
    private final double[] distance = new double[MAX_VERTICES];
    /** The buffer holding the polygon after {@link #clipToBox}. */
    private double[] polygon;
    /** Per axis, the triangle's own bounds and the padding of its clipped bounds ({@link #ownBounds}). */
    private final double[] ownMin = new double[3], ownMax = new double[3], pad = new double[3];
    /** The bounds of the two halves in {@link #clipSplit}: min x, y, z, then max x, y, z. */
    private final double[] lower = new double[6], upper = new double[6];

    /** {@return this thread's clipper} */
    public static TriangleClipper forThread() {
        return PER_THREAD.get();
    }

    /**
     * Bounds of the part inside {@code box} of the triangle whose corners are the points
     * {@code i0, i1, i2} (indices of x, y, z triples) of {@code vertices}; {@code dest} is set
     * empty when the triangle misses the box. Same result as {@link PolygonClipper#clip} on the three corners.
     * @param vertices x, y, z per vertex
     * @param i0 the first corner's vertex index
     * @param i1 the second corner's vertex index
     * @param i2 the third corner's vertex index
     * @param box the voxel to clip to
     * @param dest receives the bounds
     * @return {@code dest}
     */
    public Box clip(double[] vertices, int i0, int i1, int i2, Box box, Box dest) {
        int p0 = 3 * i0, p1 = 3 * i1, p2 = 3 * i2;
        ownBounds(vertices, p0, p1, p2);
        int count = clipToBox(vertices, p0, p1, p2, box);
        if (count == 0) return dest.setEmpty();
        for (int axis = 0; axis < 3; axis++) bound(polygon, count, axis, box.min(axis), box.max(axis), dest);
        return dest;
    }

    /**
     * Bounds of the parts inside {@code box} of the triangle {@code i0, i1, i2} below and above the
     * plane {@code x_axis = xi}: into {@code left} and {@code right}, each set empty when that part
     * is. Both are padded and clamped to their half of the box as {@link #clip} does; they may
     * differ from clipping to each half from scratch by rounding, never beyond the padding.
     * @param vertices x, y, z per vertex
     * @param i0 the first corner's vertex index
     * @param i1 the second corner's vertex index
     * @param i2 the third corner's vertex index
     * @param box the voxel being split
     * @param axis the split plane's axis
     * @param xi the split plane's position
     * @param left receives the bounds of the part below the plane
     * @param right receives the bounds of the part above the plane
     */
    public void clipSplit(double[] vertices, int i0, int i1, int i2, Box box, int axis, double xi, Box left, Box right) {
        int p0 = 3 * i0, p1 = 3 * i1, p2 = 3 * i2;
        ownBounds(vertices, p0, p1, p2);
        int count = clipToBox(vertices, p0, p1, p2, box);
        splitBounds(polygon, count, axis, xi);
        halfBounds(lower, box, axis, xi, false, left);
        halfBounds(upper, box, axis, xi, true, right);
    }

    /**
     * The points of both halves of the polygon cut at {@code x_axis = xi}, in one pass over its
     * edges, gathered straight into bounds ({@link #lower}, {@link #upper}: min then max per axis,
     * empty if no point): each half gets the vertices on its side and the points where an edge
     * crosses the plane, exactly the points {@link #clipHalf} would make for it. Where an edge
     * crosses for both halves the crossing point is computed once: the two halves' distances are
     * negatives of each other, so their ratios t are the same double.
     */
    private void splitBounds(double[] poly, int count, int axis, double xi) {
        double[] lo = lower, up = upper;
        lo[0] = lo[1] = lo[2] = up[0] = up[1] = up[2] = Double.POSITIVE_INFINITY;
        lo[3] = lo[4] = lo[5] = up[3] = up[4] = up[5] = Double.NEGATIVE_INFINITY;
        if (count == 0) return;
        double belowNext = xi - poly[axis], aboveNext = poly[axis] - xi;
        for (int i = 0; i < count; i++) {
            int p = 3 * i, q = i + 1 == count ? 0 : p + 3;
            double below = belowNext, above = aboveNext;
            belowNext = xi - poly[q + axis];
            aboveNext = poly[q + axis] - xi;
            boolean inLower = below >= 0, inUpper = above >= 0;
            if (inLower) include(lo, poly[p], poly[p + 1], poly[p + 2]);
            if (inUpper) include(up, poly[p], poly[p + 1], poly[p + 2]);
            if (count < 2) continue;
            boolean crossLower = inLower != (belowNext >= 0), crossUpper = inUpper != (aboveNext >= 0);
            if (!crossLower && !crossUpper) continue;
            double t = crossLower ? below / (below - belowNext) : above / (above - aboveNext);
            double x = poly[p] + t * (poly[q] - poly[p]);
            double y = poly[p + 1] + t * (poly[q + 1] - poly[p + 1]);
            double z = poly[p + 2] + t * (poly[q + 2] - poly[p + 2]);
            if (axis == 0) x = xi;
            else if (axis == 1) y = xi;
            else z = xi;
            if (crossLower) include(lo, x, y, z);
            if (crossUpper) include(up, x, y, z);
        }
    }

    private static void include(double[] bounds, double x, double y, double z) {
        if (x < bounds[0]) bounds[0] = x;
        if (x > bounds[3]) bounds[3] = x;
        if (y < bounds[1]) bounds[1] = y;
        if (y > bounds[4]) bounds[4] = y;
        if (z < bounds[2]) bounds[2] = z;
        if (z > bounds[5]) bounds[5] = z;
    }

    /** One half's gathered bounds, padded and clamped as {@link #bound} does, into {@code dest}. */
    private void halfBounds(double[] bounds, Box box, int axis, double xi, boolean above, Box dest) {
        if (!(bounds[0] <= bounds[3])) {
            dest.setEmpty();
            return;
        }
        for (int a = 0; a < 3; a++) {
            double lo = a == axis && above ? xi : box.min(a), hi = a == axis && !above ? xi : box.max(a);
            dest.setMin(a, Math.max(Math.max(bounds[a] - pad[a], ownMin[a]), lo));
            dest.setMax(a, Math.min(Math.min(bounds[3 + a] + pad[a], ownMax[a]), hi));
        }
    }

    /**
     * Clips the triangle at vertex offsets p0, p1, p2 to the box; the polygon is left in
     * {@link #polygon}. Needs {@link #ownBounds} first: a face the triangle's own bounds do not
     * cross is passed over without computing distances (most faces, for the small triangles of a
     * mesh), which is exact until a pass has cut the triangle.
     */
    private int clipToBox(double[] vertices, int p0, int p1, int p2, Box box) {
        double[] src = a, dst = b;
        src[0] = vertices[p0]; src[1] = vertices[p0 + 1]; src[2] = vertices[p0 + 2];
        src[3] = vertices[p1]; src[4] = vertices[p1 + 1]; src[5] = vertices[p1 + 2];
        src[6] = vertices[p2]; src[7] = vertices[p2 + 1]; src[8] = vertices[p2 + 2];
        int count = 3;
        boolean cut = false;
        for (int pass = 0; pass < 6 && count > 0; pass++) {
            int axis = pass >> 1;
            boolean keepAbove = (pass & 1) == 0;   // the lower face keeps x >= min, the upper x <= max
            double plane = keepAbove ? box.min(axis) : box.max(axis);
            // while the polygon is still the triangle, its own bounds answer "all inside?" as its distances would
            if (!cut && (keepAbove ? ownMin[axis] >= plane : ownMax[axis] <= plane)) continue;
            if (distances(src, count, axis, plane, keepAbove)) continue;   // all inside: the pass would copy src unchanged
            cut = true;
            count = clipHalf(src, dst, count, axis, plane);
            double[] t = src; src = dst; dst = t;
        }
        polygon = src;
        return count;
    }

    /** The triangle's own bounds and the padding of its clipped bounds on each axis, as PolygonClipper computes them. */
    private void ownBounds(double[] vertices, int p0, int p1, int p2) {
        for (int axis = 0; axis < 3; axis++) {
            double v0 = vertices[p0 + axis], v1 = vertices[p1 + axis], v2 = vertices[p2 + axis];
            ownMin[axis] = Math.min(Math.min(Math.min(Double.POSITIVE_INFINITY, v0), v1), v2);
            ownMax[axis] = Math.max(Math.max(Math.max(Double.NEGATIVE_INFINITY, v0), v1), v2);
            double scale = Math.max(Math.max(Math.max(0, Math.abs(v0)), Math.abs(v1)), Math.abs(v2));
            pad[axis] = PolygonClipper.PAD * scale + Double.MIN_NORMAL;
        }
    }

    /**
     * The axis's bounds of the clipped polygon, padded outward, then clamped to the triangle's own
     * bounds ({@link #ownBounds}, computed first) and to {@code [lo, hi]} (the clipping box), as
     * PolygonClipper does.
     */
    private void bound(double[] polygon, int count, int axis, double lo, double hi, Box dest) {
        double min = Double.POSITIVE_INFINITY, max = Double.NEGATIVE_INFINITY;
        for (int i = axis; i < 3 * count; i += 3) {
            double v = polygon[i];
            if (v < min) min = v;
            if (v > max) max = v;
        }
        dest.setMin(axis, Math.max(Math.max(min - pad[axis], ownMin[axis]), lo));
        dest.setMax(axis, Math.min(Math.min(max + pad[axis], ownMax[axis]), hi));
    }

    /**
     * The signed distance of each vertex to the plane, positive on the kept side, into
     * {@link #distance}; returns whether every vertex is on the kept side (so the pass may be skipped).
     */
    private boolean distances(double[] polygon, int count, int axis, double plane, boolean keepAbove) {
        boolean all = true;
        for (int i = 0, at = axis; i < count; i++, at += 3) {
            double d = distance(polygon[at], plane, keepAbove);
            distance[i] = d;
            all &= d >= 0;
        }
        return all;
    }

    /**
     * Writes the part of {@code src} on the kept side of the plane {@code x_axis = plane} to
     * {@code dst}, from the vertices' distances ({@link #distances}, computed first).
     */
    private int clipHalf(double[] src, double[] dst, int count, int axis, double plane) {
        double[] dist = distance;
        int out = 0;
        double dq = dist[0];
        for (int i = 0; i < count; i++) {
            int p = 3 * i, next = i + 1 == count ? 0 : i + 1, q = 3 * next;
            double dp = dq;
            dq = dist[next];
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
