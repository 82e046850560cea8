package org.kdtree.render;

/** A small immutable 3-vector for shading: points, directions and RGB colours alike. */
public record Vec3(double x, double y, double z) {
    public static final Vec3 ZERO = new Vec3(0, 0, 0);
    public static final Vec3 ONE = new Vec3(1, 1, 1);

    public Vec3 plus(Vec3 o) { return new Vec3(x + o.x, y + o.y, z + o.z); }
    public Vec3 minus(Vec3 o) { return new Vec3(x - o.x, y - o.y, z - o.z); }
    public Vec3 times(double s) { return new Vec3(x * s, y * s, z * s); }
    /** Component-wise product (colour filtering). */
    public Vec3 times(Vec3 o) { return new Vec3(x * o.x, y * o.y, z * o.z); }
    public double dot(Vec3 o) { return x * o.x + y * o.y + z * o.z; }
    public Vec3 cross(Vec3 o) { return new Vec3(y * o.z - z * o.y, z * o.x - x * o.z, x * o.y - y * o.x); }
    public double length() { return Math.sqrt(dot(this)); }
    public Vec3 normalized() {
        double l = length();
        return l > 0 ? times(1 / l) : this;
    }
    public Vec3 negate() { return new Vec3(-x, -y, -z); }
    /** The largest absolute component: the magnitude that rounding errors scale with. */
    public double maxAbs() { return Math.max(Math.abs(x), Math.max(Math.abs(y), Math.abs(z))); }
    /** The largest component (path weights). */
    public double max() { return Math.max(x, Math.max(y, z)); }
    public boolean isZero() { return x == 0 && y == 0 && z == 0; }
    public double get(int axis) { return axis == 0 ? x : axis == 1 ? y : z; }
}
