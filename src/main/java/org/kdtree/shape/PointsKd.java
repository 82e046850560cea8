package org.kdtree.shape;

import org.kdtree.geom.Box;
import org.kdtree.geom.Tolerance;

/** Points in k dimensions held in one flat array: the classic k-d tree of the talk's section 2. */
public final class PointsKd implements Primitives {
    private final int k;
    private final double[] coords;

    /**
     * Points in k dimensions.
     *
     * @param k the dimension, at least 1
     * @param coords k coordinates per point, point after point (not copied)
     * @throws InvalidGeometryException for a non-finite coordinate, or points outside the range the
     *         queries support ({@link Tolerance#MAX_COORDINATE}, {@link Tolerance#MIN_EXTENT})
     */
    public PointsKd(int k, double[] coords) {
        if (k < 1) throw new IllegalArgumentException("dimension must be >= 1, got " + k);
        if (coords.length % k != 0)
            throw new IllegalArgumentException(coords.length + " coordinates do not make whole " + k + "-D points");
        this.k = k;
        this.coords = coords;
        for (int i = 0; i < coords.length; i++) {
            if (!Double.isFinite(coords[i]))
                throw new InvalidGeometryException(describe(i / k) + " has a non-finite coordinate (" + coords[i] + ")");
            if (Math.abs(coords[i]) > Tolerance.MAX_COORDINATE)
                throw new InvalidGeometryException(describe(i / k) + " has the coordinate " + coords[i]
                        + ": the supported range is -1e100 .. 1e100 (squared distances would overflow); scale the points down");
        }
        checkExtent();
    }

    /** Refuses points that differ by less than {@link Tolerance#MIN_EXTENT} on every axis, but not all by 0: squared distances would underflow. */
    private void checkExtent() {
        double largest = 0;
        for (int a = 0; a < k; a++) {
            double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
            for (int i = a; i < coords.length; i += k) { lo = Math.min(lo, coords[i]); hi = Math.max(hi, coords[i]); }
            if (hi > lo) largest = Math.max(largest, hi - lo);
        }
        if (largest > 0 && largest < Tolerance.MIN_EXTENT)
            throw new InvalidGeometryException("the points span only " + largest + ": the smallest supported extent is 1e-100"
                    + " (squared distances would underflow); scale the points up");
    }

    /**
     * {@return coordinate {@code axis} of point {@code i}}
     *
     * @param i the point's index
     * @param axis the axis
     */
    public double coord(int i, int axis) { return coords[i * k + axis]; }

    @Override public int dimension() { return k; }
    @Override public int size() { return coords.length / k; }

    @Override public void bounds(int i, Box dest) {
        for (int a = 0; a < k; a++) dest.setMin(a, coords[i * k + a]).setMax(a, coords[i * k + a]);
    }

    @Override public void clip(int i, Box voxel, Box dest) {
        bounds(i, dest);
        for (int a = 0; a < k; a++) {
            if (dest.min(a) < voxel.min(a) || dest.max(a) > voxel.max(a)) {
                dest.setEmpty();
                return;
            }
        }
    }

    @Override public String describe(int i) { return "point " + i; }
}
