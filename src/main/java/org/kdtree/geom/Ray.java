package org.kdtree.geom;

/**
 * A ray {@code o + t d} in k dimensions. Mutable and reusable, so that hot loops allocate
 * nothing per ray. The direction is not normalised: t is the ray parameter. Direction
 * components may be +0.0 or -0.0 (rays parallel to an axis plane); their inverses, kept
 * alongside, are then +infinity or -infinity.
 */
public final class Ray {
    private final double[] origin;
    private final double[] direction;
    private final double[] inverse;

    /**
     * A ray in {@code k} dimensions with origin and direction all zero; {@link #set} it before use.
     *
     * @param k the dimension
     */
    public Ray(int k) {
        origin = new double[k];
        direction = new double[k];
        inverse = new double[k];
    }

    /**
     * A ray with the given origin and direction (copied).
     *
     * @param origin o, the ray's origin
     * @param direction d, its direction, not all zero
     */
    public Ray(double[] origin, double[] direction) {
        this(origin.length);
        set(origin, direction);
    }

    /** {@return k, the dimension} */
    public int dimension() { return origin.length; }

    /**
     * Sets origin and direction (copied); the direction must not be all zero.
     *
     * @param o the origin
     * @param d the direction
     * @return this ray
     */
    public Ray set(double[] o, double[] d) {
        for (int a = 0; a < origin.length; a++) {
            origin[a] = o[a];
            direction[a] = d[a];
            inverse[a] = 1.0 / d[a];
        }
        return this;
    }

    /**
     * Sets a 3-D ray.
     *
     * @param ox origin x
     * @param oy origin y
     * @param oz origin z
     * @param dx direction x
     * @param dy direction y
     * @param dz direction z
     * @return this ray
     */
    public Ray set(double ox, double oy, double oz, double dx, double dy, double dz) {
        origin[0] = ox; origin[1] = oy; origin[2] = oz;
        direction[0] = dx; direction[1] = dy; direction[2] = dz;
        inverse[0] = 1.0 / dx; inverse[1] = 1.0 / dy; inverse[2] = 1.0 / dz;
        return this;
    }

    /**
     * Sets a 2-D ray.
     *
     * @param ox origin x
     * @param oy origin y
     * @param dx direction x
     * @param dy direction y
     * @return this ray
     */
    public Ray set(double ox, double oy, double dx, double dy) {
        origin[0] = ox; origin[1] = oy;
        direction[0] = dx; direction[1] = dy;
        inverse[0] = 1.0 / dx; inverse[1] = 1.0 / dy;
        return this;
    }

    /**
     * {@return coordinate {@code axis} of the origin}
     *
     * @param axis the axis
     */
    public double origin(int axis) { return origin[axis]; }
    /**
     * {@return component {@code axis} of the direction}
     *
     * @param axis the axis
     */
    public double direction(int axis) { return direction[axis]; }
    /**
     * {@return {@code 1 / direction(axis)}}, +-infinity for a zero component of either sign.
     *
     * @param axis the axis
     */
    public double inverseDirection(int axis) { return inverse[axis]; }

    /**
     * {@return coordinate {@code axis} of the point at parameter t}
     *
     * @param t the ray parameter
     * @param axis the axis
     */
    public double at(double t, int axis) { return origin[axis] + t * direction[axis]; }

    /**
     * Checks that the ray can be traced through a {@code k}-D structure: of that dimension,
     * with a finite origin and a finite, non-zero direction.
     *
     * @param k         the structure's dimension
     * @param structure what it is, for the message, e.g. "tree"
     * @throws IllegalArgumentException naming what is wrong
     */
    public void requireTraceable(int k, String structure) {
        if (dimension() != k)
            throw new IllegalArgumentException("a " + dimension() + "-D ray in a " + k + "-D " + structure);
        boolean moving = false;
        for (int a = 0; a < k; a++) {
            if (!Double.isFinite(origin[a]) || !Double.isFinite(direction[a]))
                throw new IllegalArgumentException("ray has a non-finite origin or direction: " + this);
            moving |= direction[a] != 0;
        }
        if (!moving) throw new IllegalArgumentException("ray direction is zero: " + this);
    }

    @Override public String toString() {
        return "Ray[o=" + java.util.Arrays.toString(origin) + ", d=" + java.util.Arrays.toString(direction) + "]";
    }
}
