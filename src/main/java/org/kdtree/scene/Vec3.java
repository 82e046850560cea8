package org.kdtree.scene;

/**
 * A small immutable 3-vector for describing scenes: points, directions and RGB colours alike.
 * The tracer does not use it per ray (it allocates); it works on arrays with {@link Vectors}.
 */
public record Vec3(double x, double y, double z) {
    /** The zero vector (black). */
    public static final Vec3 ZERO = new Vec3(0, 0, 0);
    /** (1, 1, 1) (white). */
    public static final Vec3 ONE = new Vec3(1, 1, 1);

    /**
     * {@return this + o}
     *
     * @param o the other vector
     */
    public Vec3 plus(Vec3 o) { return new Vec3(x + o.x, y + o.y, z + o.z); }
    /**
     * {@return this - o}
     *
     * @param o the other vector
     */
    public Vec3 minus(Vec3 o) { return new Vec3(x - o.x, y - o.y, z - o.z); }
    /**
     * {@return this scaled by {@code s}}
     *
     * @param s the factor
     */
    public Vec3 times(double s) { return new Vec3(x * s, y * s, z * s); }
    /**
     * {@return the component-wise product} (colour filtering).
     *
     * @param o the other vector
     */
    public Vec3 times(Vec3 o) { return new Vec3(x * o.x, y * o.y, z * o.z); }
    /**
     * {@return the dot product}
     *
     * @param o the other vector
     */
    public double dot(Vec3 o) { return x * o.x + y * o.y + z * o.z; }
    /**
     * {@return the cross product this x o}
     *
     * @param o the other vector
     */
    public Vec3 cross(Vec3 o) { return new Vec3(y * o.z - z * o.y, z * o.x - x * o.z, x * o.y - y * o.x); }
    /** {@return the Euclidean length} */
    public double length() { return Math.sqrt(dot(this)); }
    /** {@return this scaled to unit length}, or this when it is zero. */
    public Vec3 normalized() {
        double l = length();
        return l > 0 ? times(1 / l) : this;
    }
    /** {@return -this} */
    public Vec3 negate() { return new Vec3(-x, -y, -z); }
    /** {@return whether all components are zero} */
    public boolean isZero() { return x == 0 && y == 0 && z == 0; }
}
