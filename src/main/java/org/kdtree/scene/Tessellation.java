package org.kdtree.scene;

import org.kdtree.limits.Limits;

/** The built-in shapes, tessellated into a {@link GeometryBuilder}, whose methods of the same names are their public door. */
final class Tessellation {
    private Tessellation() {
    }

    /** {@link GeometryBuilder#sphere}, into {@code g}. */
    static void sphere(GeometryBuilder g, Vec3 center, double radius, int segments, int rings, int material) {
        Limits.SPHERE_SEGMENTS.check("segments", segments);
        Limits.SPHERE_RINGS.check("rings", rings);
        int north = g.vertex(center.plus(new Vec3(0, radius, 0)), new Vec3(0, 1, 0));
        int first = g.vertexCount();
        for (int r = 1; r < rings; r++) {
            double theta = Math.PI * r / rings;
            for (int s = 0; s < segments; s++) {
                double phi = 2 * Math.PI * s / segments;
                Vec3 n = new Vec3(Math.sin(theta) * Math.cos(phi), Math.cos(theta), -Math.sin(theta) * Math.sin(phi));
                g.vertex(center.plus(n.times(radius)), n);
            }
        }
        int south = g.vertex(center.plus(new Vec3(0, -radius, 0)), new Vec3(0, -1, 0));
        for (int s = 0; s < segments; s++) {
            int s1 = (s + 1) % segments;
            g.triangle(north, first + s, first + s1, material, true);
            for (int r = 0; r + 2 < rings; r++) {
                int a = first + r * segments + s, b = first + r * segments + s1;
                int c = a + segments, d = b + segments;
                g.triangle(a, c, d, material, true);
                g.triangle(a, d, b, material, true);
            }
            int last = first + (rings - 2) * segments;
            g.triangle(south, last + s1, last + s, material, true);
        }
    }

    /** {@link GeometryBuilder#box}, into {@code g}. */
    static void box(GeometryBuilder g, Vec3 min, Vec3 max, int material) {
        double x0 = min.x(), y0 = min.y(), z0 = min.z(), x1 = max.x(), y1 = max.y(), z1 = max.z();
        g.quad(new Vec3(x0, y0, z1), new Vec3(x1, y0, z1), new Vec3(x1, y1, z1), new Vec3(x0, y1, z1), material); // +z
        g.quad(new Vec3(x1, y0, z0), new Vec3(x0, y0, z0), new Vec3(x0, y1, z0), new Vec3(x1, y1, z0), material); // -z
        g.quad(new Vec3(x1, y0, z1), new Vec3(x1, y0, z0), new Vec3(x1, y1, z0), new Vec3(x1, y1, z1), material); // +x
        g.quad(new Vec3(x0, y0, z0), new Vec3(x0, y0, z1), new Vec3(x0, y1, z1), new Vec3(x0, y1, z0), material); // -x
        g.quad(new Vec3(x0, y1, z1), new Vec3(x1, y1, z1), new Vec3(x1, y1, z0), new Vec3(x0, y1, z0), material); // +y
        g.quad(new Vec3(x0, y0, z0), new Vec3(x1, y0, z0), new Vec3(x1, y0, z1), new Vec3(x0, y0, z1), material); // -y
    }

    /** {@link GeometryBuilder#plane}, into {@code g}. */
    static void plane(GeometryBuilder g, Vec3 center, Vec3 normal, double width, double height, int material) {
        Vec3 n = normal.normalized();
        Vec3 a = Math.abs(n.y()) < 0.9 ? new Vec3(0, 1, 0) : new Vec3(0, 0, -1);
        Vec3 u = a.cross(n).normalized().times(width / 2);
        Vec3 v = n.cross(u).normalized().times(height / 2);
        g.quad(center.minus(u).minus(v), center.plus(u).minus(v), center.plus(u).plus(v), center.minus(u).plus(v),
                material);
    }

    /** {@link GeometryBuilder#sphereflake}, into {@code g}. */
    static void sphereflake(GeometryBuilder g, Vec3 center, double radius, int levels, int segments,
                                   int rings, int material) {
        Limits.FLAKE_LEVELS.check("levels", levels);
        flake(g, center, radius, new Vec3(0, 1, 0), levels, segments, rings, material);
    }

    private static void flake(GeometryBuilder g, Vec3 c, double r, Vec3 axis, int levels, int seg, int rings, int m) {
        sphere(g, c, r, seg, rings, m);
        if (levels == 0) return;
        Vec3 t1 = (Math.abs(axis.x()) < 0.9 ? new Vec3(1, 0, 0) : new Vec3(0, 1, 0)).cross(axis).normalized();
        Vec3 t2 = axis.cross(t1);
        double childR = r / 3;
        for (int i = 0; i < 9; i++) {
            // six around the equator, three higher up, all on the side facing away from the parent
            double elevation = i < 6 ? Math.toRadians(10) : Math.toRadians(55);
            double azimuth = i < 6 ? i * Math.PI / 3 : (i - 6) * 2 * Math.PI / 3 + Math.PI / 6;
            Vec3 dir = axis.times(Math.sin(elevation))
                    .plus(t1.times(Math.cos(elevation) * Math.cos(azimuth)))
                    .plus(t2.times(Math.cos(elevation) * Math.sin(azimuth))).normalized();
            flake(g, c.plus(dir.times(r + childR)), childR, dir, levels - 1, seg, rings, m);
        }
    }
}
