package org.kdtree.shape;

import org.kdtree.geom.Box;

/** Points in k dimensions held in one flat array: the classic k-d tree of the talk's section 2. */
public final class PointsKd implements Primitives {
    private final int k;
    private final double[] coords;

    /**
     * Points in k dimensions.
     *
     * @param k the dimension, at least 1
     * @param coords k coordinates per point, point after point (not copied)
     */
    public PointsKd(int k, double[] coords) {
        if (k < 1) throw new IllegalArgumentException("dimension must be >= 1, got " + k);
        if (coords.length % k != 0)
            throw new IllegalArgumentException(coords.length + " coordinates do not make whole " + k + "-D points");
        this.k = k;
        this.coords = coords;
        for (int i = 0; i < coords.length; i++)
            if (!Double.isFinite(coords[i]))
                throw new InvalidGeometryException(describe(i / k) + " has a non-finite coordinate (" + coords[i] + ")");
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
