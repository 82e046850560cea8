package org.kdtree.tree;

import org.kdtree.geom.Box;

/**
 * Where a tree can place its split planes: on each axis, the positions {@code base + u * scale}
 * for a {@code float} u in [-1, 1] (computed in double, exactly as written here), where scale is
 * a power of two (so {@code u * scale} is exact) covering the root voxel. A node stores u in 4
 * bytes, so that a node fits in 8 (as in pbrt), and {@link #position} gives back exactly the
 * plane the build partitioned with.
 *
 * <p>The base is 0 when the root voxel contains the origin or lies near it (within its own
 * extent): the grid is then all the {@code float} values there, so "round" coordinates such as 6
 * or 0.25 stay exact planes. Far from the origin the base is the voxel's centre: a plain float
 * would be coarse there (a scene of size 1 at 10^6 would get planes every 1/16), and beyond
 * 3.4e38 or below 1e-38 it would not exist at all. Either way the grid's spacing is at most 2^-24
 * of the voxel's extent on the axis, at every scale the limits allow.
 *
 * <p>Builders choose planes anywhere; the build moves each chosen plane to the nearest grid
 * position inside the voxel ({@link #nearest}) before it partitions, so primitives are sorted to
 * the children by the plane the tree stores, and none ever leaves a voxel it overlaps.
 */
public final class SplitGrid {
    /**
     * Codes are ordered ints k in [-ONE, ONE] standing for the floats u in [-1, 1] in increasing
     * order ({@link #toFloat}); ONE is the bits of 1.0f.
     */
    private static final int ONE = Float.floatToRawIntBits(1f);
    /** Below this |u| floats are subnormal and the fast paths' exactness argument fails: search instead. */
    private static final double MIN_EXACT = 0x1p-120;

    private final double[] base, scale, inverseScale;

    /**
     * The grid of a tree whose root voxel is {@code root}.
     *
     * @param root the root voxel (finite)
     */
    public SplitGrid(Box root) {
        int k = root.dimension();
        base = new double[k];
        scale = new double[k];
        inverseScale = new double[k];
        for (int a = 0; a < k; a++) {
            double lo = root.min(a), hi = root.max(a), centre = lo + 0.5 * (hi - lo);
            base[a] = Math.abs(centre) <= hi - lo || (lo <= 0 && hi >= 0) ? 0 : centre;
            scale[a] = powerOfTwoAtLeast(Math.max(Math.abs(lo - base[a]), Math.abs(hi - base[a])));
            inverseScale[a] = 1 / scale[a]; // exact: a power of two
        }
    }

    private static double powerOfTwoAtLeast(double d) {
        if (!(d > 0)) return 1;
        double p = Math.scalb(1.0, Math.getExponent(d));
        return p < d ? 2 * p : p;
    }

    /** {@return the number of axes} */
    public int dimension() { return base.length; }

    /**
     * The plane position of a stored code: the tree's one decoding, used by every reader.
     *
     * @param axis the axis
     * @param u the stored code (in [-1, 1])
     * @return {@code base[axis] + u * scale[axis]}, computed in double
     */
    public double position(int axis, float u) {
        return base[axis] + u * scale[axis];
    }

    /**
     * The code of a position on the grid.
     *
     * @param axis the axis
     * @param x a position returned by {@link #nearest} (or {@link #position})
     * @return u with {@code position(axis, u) == x}
     * @throws IllegalArgumentException if {@code x} is not on the grid
     */
    public float code(int axis, double x) {
        int c = ceiling(axis, x);
        if (c > ONE || position(axis, c) != x)
            throw new IllegalArgumentException("x" + axis + " = " + x + " is not a split position of this tree's grid "
                    + "(move it with SplitGrid.nearest)");
        return toFloat(c);
    }

    /**
     * The grid position nearest {@code x} among those in {@code [lo, hi]} (a voxel's extent on
     * {@code axis}), or NaN when the grid has none there (the voxel is narrower than the grid's
     * spacing: it is a leaf).
     *
     * @param axis the axis
     * @param x the plane a builder chose, in {@code [lo, hi]}
     * @param lo the voxel's lower bound on {@code axis}
     * @param hi the voxel's upper bound on {@code axis}
     * @return a position on the grid in {@code [lo, hi]}, or NaN
     */
    public double nearest(int axis, double x, double lo, double hi) {
        double above = atOrAbove(axis, x), below = atOrBelow(axis, x);
        boolean aboveFits = above <= hi, belowFits = below >= lo;
        if (aboveFits && belowFits) return above - x <= x - below ? above : below;
        return aboveFits ? above : belowFits ? below : Double.NaN;
    }

    /**
     * {@return the least grid position at or above {@code x}, or NaN if none}
     * @param axis the axis
     * @param x a position
     */
    public double atOrAbove(int axis, double x) {
        int c = ceiling(axis, x);
        return c <= ONE ? position(axis, c) : Double.NaN;
    }

    /**
     * {@return the greatest grid position at or below {@code x}, or NaN if none}
     * @param axis the axis
     * @param x a position
     */
    public double atOrBelow(int axis, double x) {
        if (base[axis] == 0) {
            double u = x * inverseScale[axis];
            if (Math.abs(u) >= MIN_EXACT && Math.abs(u) <= 1) {
                int c = toCode((float) u);
                return position(axis, toFloat(c) > u ? c - 1 : c);
            }
        }
        int c = ceiling(axis, x);
        if (c <= ONE && position(axis, c) == x) return x;
        return c > -ONE ? position(axis, c - 1) : Double.NaN;
    }

    /** Two grids are equal when they place planes at the same positions. */
    @Override public boolean equals(Object o) {
        return o instanceof SplitGrid g && java.util.Arrays.equals(base, g.base) && java.util.Arrays.equals(scale, g.scale);
    }

    @Override public int hashCode() {
        return 31 * java.util.Arrays.hashCode(base) + java.util.Arrays.hashCode(scale);
    }

    /** The float of ordered code k: k's bits for k at or above 0, the negated float of -k below. */
    private static float toFloat(int k) {
        return k >= 0 ? Float.intBitsToFloat(k) : -Float.intBitsToFloat(-k);
    }

    private static int toCode(float u) {
        int bits = Float.floatToRawIntBits(u) & 0x7fffffff;
        return u < 0 ? -bits : bits;
    }

    private double position(int axis, int code) {
        return position(axis, toFloat(code));
    }

    /**
     * The least code (-ONE .. ONE) whose position is at least {@code x}, or ONE + 1 if none:
     * positions never decrease with the code, so a search from a close guess finds it in a few steps.
     */
    private int ceiling(int axis, double x) {
        if (base[axis] == 0) {
            // position(u) = u * scale exactly, and so is x / scale (both powers of two), away from
            // underflow: the float nearest x / scale, or the next one up, is the answer.
            double u = x * inverseScale[axis];
            if (Math.abs(u) >= MIN_EXACT && Math.abs(u) <= 1) {
                int c = toCode((float) u);
                return toFloat(c) < u ? c + 1 : c;
            }
        }
        if (!(x > position(axis, -ONE))) return -ONE;
        if (position(axis, ONE) < x) return ONE + 1;
        double u = (x - base[axis]) / scale[axis];
        int guess = toCode((float) Math.min(1, Math.max(-1, u)));
        // Bracket: position(lo) < x <= position(hi), widening by doubling steps from the guess.
        int lo, hi;
        if (position(axis, guess) >= x) {
            hi = guess;
            int step = 1;
            lo = Math.max(-ONE, hi - step);
            while (lo > -ONE && position(axis, lo) >= x) {
                hi = lo;
                step <<= 1;
                lo = Math.max(-ONE, hi - step);
            }
        } else {
            lo = guess;
            int step = 1;
            hi = Math.min(ONE, lo + step);
            while (position(axis, hi) < x) {
                lo = hi;
                step <<= 1;
                hi = Math.min(ONE, lo + step);
            }
        }
        while (hi - lo > 1) {
            int mid = (lo + hi) >> 1;
            if (position(axis, mid) >= x) hi = mid; else lo = mid;
        }
        return position(axis, lo) >= x ? lo : hi;
    }
}
