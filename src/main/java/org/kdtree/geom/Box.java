package org.kdtree.geom;

import java.util.Arrays;

/**
 * An axis-aligned box in k dimensions: a voxel of the kd-tree, or the bounds of a primitive.
 *
 * <p>Boxes are mutable so that hot code can write into a reused destination (as JOML does);
 * code that keeps a box copies it with {@link #copy()}. A box is <em>empty</em> when
 * {@code min > max} on some axis; a box of zero extent on an axis is <em>flat</em> but not
 * empty (a triangle lying in a plane has flat bounds).
 */
public final class Box {
    private final double[] min;
    private final double[] max;

    /**
     * An empty box in {@code k} dimensions (min = +inf, max = -inf), ready to be grown.
     *
     * @param k the dimension, at least 1
     */
    public Box(int k) {
        if (k < 1) throw new IllegalArgumentException("dimension must be >= 1, got " + k);
        min = new double[k];
        max = new double[k];
        setEmpty();
    }

    /**
     * A box with the given corners (copied).
     *
     * @param min the lower corner: the smallest coordinate on each axis
     * @param max the upper corner, of the same dimension
     */
    public Box(double[] min, double[] max) {
        if (min.length != max.length || min.length < 1)
            throw new IllegalArgumentException("corners must have the same dimension >= 1");
        this.min = min.clone();
        this.max = max.clone();
    }

    /**
     * Convenience constructor for a 2-D box.
     *
     * @param x0 the lower corner, x
     * @param y0 the lower corner, y
     * @param x1 the upper corner, x
     * @param y1 the upper corner, y
     * @return the box {@code [x0, x1] x [y0, y1]}
     */
    public static Box of2(double x0, double y0, double x1, double y1) {
        return new Box(new double[] {x0, y0}, new double[] {x1, y1});
    }

    /**
     * Convenience constructor for a 3-D box.
     *
     * @param x0 the lower corner, x
     * @param y0 the lower corner, y
     * @param z0 the lower corner, z
     * @param x1 the upper corner, x
     * @param y1 the upper corner, y
     * @param z1 the upper corner, z
     * @return the box {@code [x0, x1] x [y0, y1] x [z0, z1]}
     */
    public static Box of3(double x0, double y0, double z0, double x1, double y1, double z1) {
        return new Box(new double[] {x0, y0, z0}, new double[] {x1, y1, z1});
    }

    /** {@return k, the number of axes} */
    public int dimension() { return min.length; }

    /**
     * {@return the lower bound on an axis}
     * @param axis 0 to k - 1
     */
    public double min(int axis) { return min[axis]; }

    /**
     * {@return the upper bound on an axis}
     * @param axis 0 to k - 1
     */
    public double max(int axis) { return max[axis]; }

    /**
     * {@return max minus min on an axis} Negative for an axis on which the box is empty.
     * @param axis 0 to k - 1
     */
    public double extent(int axis) { return max[axis] - min[axis]; }

    /**
     * Sets the lower bound on an axis (a voxel's child starts at the split plane).
     *
     * @param axis 0 to k - 1
     * @param v    the new lower bound
     * @return this box
     */
    public Box setMin(int axis, double v) { min[axis] = v; return this; }

    /**
     * Sets the upper bound on an axis (a voxel's child ends at the split plane).
     *
     * @param axis 0 to k - 1
     * @param v    the new upper bound
     * @return this box
     */
    public Box setMax(int axis, double v) { max[axis] = v; return this; }

    /**
     * Makes this box empty, so that {@link #grow} starts afresh.
     *
     * @return this box
     */
    public Box setEmpty() {
        Arrays.fill(min, Double.POSITIVE_INFINITY);
        Arrays.fill(max, Double.NEGATIVE_INFINITY);
        return this;
    }

    /**
     * Makes this box a copy of {@code other}, without allocating.
     *
     * @param other a box of the same dimension
     * @return this box
     */
    public Box set(Box other) {
        System.arraycopy(other.min, 0, min, 0, min.length);
        System.arraycopy(other.max, 0, max, 0, max.length);
        return this;
    }

    /** {@return a new box with the same corners} */
    public Box copy() { return new Box(min, max); }

    /**
     * {@return the largest finite magnitude of its bounds} (0 for an empty or unbounded box): the
     * scale that tolerances relative to a scene are taken of
     */
    public double magnitude() {
        double m = 0;
        for (int a = 0; a < dimension(); a++) {
            if (Double.isFinite(min[a])) m = Math.max(m, Math.abs(min[a]));
            if (Double.isFinite(max[a])) m = Math.max(m, Math.abs(max[a]));
        }
        return m;
    }

    /** {@return the lower corner, as a new array} (for hot loops that keep the box in locals) */
    public double[] minCorner() { return min.clone(); }

    /** {@return the upper corner, as a new array} */
    public double[] maxCorner() { return max.clone(); }

    /**
     * Grows the box to contain the point {@code p} (read from {@code p[offset..offset+k)}).
     *
     * @param p      an array holding the point's k coordinates
     * @param offset where they start in {@code p}: a flat array can hold many points
     * @return this box
     */
    public Box grow(double[] p, int offset) {
        for (int a = 0; a < min.length; a++) {
            double v = p[offset + a];
            if (v < min[a]) min[a] = v;
            if (v > max[a]) max[a] = v;
        }
        return this;
    }

    /**
     * Grows the box to contain {@code other}: the bounds of a set of primitives, one at a time.
     *
     * @param other a box of the same dimension (an empty one changes nothing)
     * @return this box
     */
    public Box grow(Box other) {
        for (int a = 0; a < min.length; a++) {
            if (other.min[a] < min[a]) min[a] = other.min[a];
            if (other.max[a] > max[a]) max[a] = other.max[a];
        }
        return this;
    }

    /**
     * Shrinks this box to its intersection with {@code other} (may become empty).
     *
     * @param other a box of the same dimension
     * @return this box
     */
    public Box intersect(Box other) {
        for (int a = 0; a < min.length; a++) {
            min[a] = Math.max(min[a], other.min[a]);
            max[a] = Math.min(max[a], other.max[a]);
        }
        return this;
    }

    /** {@return true when {@code min > max} on some axis} The box then holds no point. */
    public boolean isEmpty() {
        for (int a = 0; a < min.length; a++) if (!(min[a] <= max[a])) return true;
        return false;
    }

    /** {@return true when every coordinate is finite} No NaN, no infinity. */
    public boolean isFinite() {
        for (int a = 0; a < min.length; a++)
            if (!Double.isFinite(min[a]) || !Double.isFinite(max[a])) return false;
        return true;
    }

    /**
     * {@return true when the closed box contains the point} A point on a face counts.
     * @param p the point's coordinates, at least k of them
     */
    public boolean contains(double[] p) {
        for (int a = 0; a < min.length; a++) if (p[a] < min[a] || p[a] > max[a]) return false;
        return true;
    }

    /**
     * The "surface area" the SAH needs: the sum of the measures of the 2k faces.
     * Perimeter in 2-D, area in 3-D; a flat box keeps the measure of its faces, so a
     * zero-thickness voxel still has a well-defined, positive area.
     *
     * @return the sum of the faces' measures; 0 for an empty box
     */
    public double surfaceArea() {
        int k = min.length;
        if (isEmpty()) return 0;
        double sum = 0;
        for (int skip = 0; skip < k; skip++) {
            double face = 1;
            for (int a = 0; a < k; a++) if (a != skip) face *= max[a] - min[a];
            sum += face;
        }
        return 2 * sum;
    }

    /** {@return the measure of the box: length, area or volume} 0 for an empty or flat box. */
    public double volume() {
        double v = 1;
        for (int a = 0; a < min.length; a++) v *= Math.max(0, max[a] - min[a]);
        return v;
    }

    /**
     * The part of this box below the split plane ({@code x_axis <= xi}), as a new box.
     *
     * @param axis the plane's axis
     * @param xi   the plane's position on it
     * @return the lower child's voxel
     */
    public Box lowerPart(int axis, double xi) {
        Box b = copy();
        b.max[axis] = xi;
        return b;
    }

    /**
     * The part of this box above the split plane ({@code x_axis >= xi}), as a new box.
     *
     * @param axis the plane's axis
     * @param xi   the plane's position on it
     * @return the upper child's voxel
     */
    public Box upperPart(int axis, double xi) {
        Box b = copy();
        b.min[axis] = xi;
        return b;
    }

    @Override public boolean equals(Object o) {
        return o instanceof Box b && Arrays.equals(min, b.min) && Arrays.equals(max, b.max);
    }

    @Override public int hashCode() { return 31 * Arrays.hashCode(min) + Arrays.hashCode(max); }

    @Override public String toString() {
        return "Box" + Arrays.toString(min) + ".." + Arrays.toString(max);
    }
}
