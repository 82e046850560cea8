package org.kdtree.accel;

import java.math.BigDecimal;
import org.kdtree.geom.Ray;
import org.kdtree.geom.Tolerance;
import org.kdtree.shape.Primitives;
import org.kdtree.shape.TriangleMesh;

/**
 * The watertight ray/triangle test of Woop, Benthin and Wald (2013), in double precision,
 * for a {@link TriangleMesh}.
 *
 * <p>The ray is sheared so that it runs along +z from the origin; each triangle is
 * projected onto the xy-plane of that frame, where three 2-D edge functions U, V, W decide
 * inclusion. An edge shared by two triangles is evaluated from the same two sheared vertices
 * in both, so its edge function has exactly opposite signs in the two triangles: a ray can
 * never slip between them. Edge functions equal to zero count as inside, so a ray through an
 * edge or a vertex hits (every triangle sharing it, possibly). Zero-area triangles (repeated
 * or exactly collinear vertices, decided exactly when the mesh is loaded) are never hit, and
 * neither is a triangle seen exactly edge-on (projected area zero).
 *
 * <p>The corners are copied once into one flat array, nine doubles per triangle in triangle
 * order (NaN for degenerate triangles, which then fail every comparison), so that the test reads
 * one contiguous block instead of following vertex indices. Barycentrics: {@code Hit.u}
 * belongs to corner 1, {@code Hit.v} to corner 2.
 */
public final class TriangleIntersector implements Intersector {
    private final double[] corners;
    private final int size;

    /**
     * An intersector for the mesh's triangles, with their corners copied into a flat array.
     *
     * @param mesh the triangles
     */
    public TriangleIntersector(TriangleMesh mesh) {
        this(corners(mesh));
    }

    /**
     * An intersector over corners as {@link #corners(TriangleMesh)} makes them, read in place:
     * a structure that also runs {@link #test} over the same array (its hot loop) keeps one copy.
     *
     * @param corners nine doubles per triangle, NaN for a degenerate one; the caller never changes them
     */
    public TriangleIntersector(double[] corners) {
        if (corners.length % 9 != 0) throw new IllegalArgumentException("corners come nine per triangle, not " + corners.length);
        this.size = corners.length / 9;
        this.corners = corners;
    }

    @Override public int dimension() { return 3; }
    @Override public int size() { return size; }


    /**
     * {@return whether triangle {@code t} has zero area and is therefore never hit}
     *
     * @param t the triangle's index
     */
    public boolean isDegenerate(int t) { return Double.isNaN(corners[9 * t]); }

    @Override public boolean intersect(int i, Ray ray, double tMin, double tMax, Hit hit) {
        double dx = ray.direction(0), dy = ray.direction(1), dz = ray.direction(2);
        int kz = maxAxis(dx, dy, dz);
        int kx = kz == 2 ? 0 : kz + 1, ky = kx == 2 ? 0 : kx + 1;
        double dkz = ray.direction(kz);
        if (dkz < 0) { int s = kx; kx = ky; ky = s; } // keep the winding: same sign of det on both sides
        double sz = ray.inverseDirection(kz), sx = ray.direction(kx) * sz, sy = ray.direction(ky) * sz; // = 1 / dkz
        return test(corners, 9 * i, i, ray.origin(kx), ray.origin(ky), ray.origin(kz), kx, ky, kz, sx, sy, sz,
                tMin, tMax, hit);
    }

    /**
     * {@return the axis of largest absolute direction component (the sheared frame's z)}
     *
     * @param dx the direction's x
     * @param dy its y
     * @param dz its z
     */
    public static int maxAxis(double dx, double dy, double dz) {
        double ax = Math.abs(dx), ay = Math.abs(dy), az = Math.abs(dz);
        return ax > ay ? (ax > az ? 0 : 2) : (ay > az ? 1 : 2);
    }

    /**
     * The test proper, on corners {@code c[b .. b+9)}, with the origin's coordinates given in the
     * sheared frame's axis order and the per-ray shear constants. Records a hit with
     * {@code tMin <= t <= tMax} and {@code t < hit.t} in {@code hit} (or {@code t == hit.t} and
     * {@code prim < hit.primitive}: of two hits equally close the lower index wins, in any order). At 342 bytes of
     * bytecode it is above HotSpot's limit for inlining a hot callee ({@code FreqInlineSize}, 325), so the JIT calls it
     * (JDK 17 and 25, {@code -XX:+PrintInlining}: "hot method too big"): the kd-tree's and the BVH's single-ray and packet
     * loops call it (a copy written out in a loop measured no faster); the vector path's leaf tests repeat its
     * operations lane by lane.
     *
     * @param c    corner coordinates, 9 per triangle
     * @param b    where this triangle's 9 start
     * @param prim the triangle's index, recorded in {@code hit}
     * @param ox   the ray origin's coordinate on the sheared frame's x axis ({@code kx})
     * @param oy   on its y axis
     * @param oz   on its z axis
     * @param kx   the sheared frame's x axis
     * @param ky   its y axis
     * @param kz   its z axis, {@link #maxAxis} of the direction
     * @param sx   the shear {@code d[kx] / d[kz]}
     * @param sy   the shear {@code d[ky] / d[kz]}
     * @param sz   {@code 1 / d[kz]}
     * @param tMin the start of the ray's range
     * @param tMax the end of the ray's range
     * @param hit  the closest hit so far; updated on a closer hit
     * @return whether a closer hit was recorded
     */
    public static boolean test(double[] c, int b, int prim, double ox, double oy, double oz, int kx, int ky, int kz,
                        double sx, double sy, double sz, double tMin, double tMax, Hit hit) {
        double az = c[b + kz] - oz, bz = c[b + 3 + kz] - oz, cz = c[b + 6 + kz] - oz;
        double ax = c[b + kx] - ox - sx * az, ay = c[b + ky] - oy - sy * az;
        double bx = c[b + 3 + kx] - ox - sx * bz, by = c[b + 3 + ky] - oy - sy * bz;
        double cx = c[b + 6 + kx] - ox - sx * cz, cy = c[b + 6 + ky] - oy - sy * cz;
        double u = cx * by - cy * bx, v = ax * cy - ay * cx, w = bx * ay - by * ax;
        if ((u < 0 || v < 0 || w < 0) && (u > 0 || v > 0 || w > 0)) return false;
        double det = u + v + w;
        if (det == 0) return false; // edge-on, or NaN corners never get here as hits (below)
        double t = (u * az + v * bz + w * cz) * sz / det;
        // Also rejects NaN. Of two hits equally close the lower index wins, whatever the order they
        // were tested in, so that single rays, packets and brute force give the same answer.
        if (!(t >= tMin && t <= tMax && (t < hit.t || t == hit.t && prim < hit.primitive))) return false;
        return record(hit, prim, t, v / det, w / det);
    }

    /** Kept apart to keep {@link #test} short (it is still above the JIT's inlining limit: see there). */
    private static boolean record(Hit hit, int prim, double t, double u, double v) {
        hit.primitive = prim;
        hit.t = t;
        hit.u = u;
        hit.v = v;
        return true;
    }

    /**
     * The closest hit over all triangles, by brute force with the per-ray shear computed once: the
     * same answers as {@link BruteForce} on this intersector, faster (for checking large runs).
     * @param ray the ray
     * @param tMin the start of the ray's range
     * @param tMax the end of the ray's range
     * @param hit receives the closest hit
     * @return whether the ray hit a triangle
     */
    public boolean closestHitAll(Ray ray, double tMin, double tMax, Hit hit) {
        hit.reset();
        double dx = ray.direction(0), dy = ray.direction(1), dz = ray.direction(2);
        int kz = maxAxis(dx, dy, dz);
        int kx = kz == 2 ? 0 : kz + 1, ky = kx == 2 ? 0 : kx + 1;
        double dkz = ray.direction(kz);
        if (dkz < 0) { int s = kx; kx = ky; ky = s; }
        double sz = ray.inverseDirection(kz), sx = ray.direction(kx) * sz, sy = ray.direction(ky) * sz; // = 1 / dkz
        double ox = ray.origin(kx), oy = ray.origin(ky), oz = ray.origin(kz);
        boolean found = false;
        for (int i = 0; i < size; i++)
            found |= test(corners, 9 * i, i, ox, oy, oz, kx, ky, kz, sx, sy, sz, tMin, tMax, hit);
        return found;
    }

    /**
     * {@return a new array of the corners ({@link #corners(TriangleMesh)}) if {@code primitives} is a mesh, else null}
     * @param primitives any primitives
     */
    public static double[] cornersOf(Primitives primitives) {
        return primitives instanceof TriangleMesh mesh ? corners(mesh) : null;
    }

    /**
     * {@return a new array of the mesh's corners}: x, y, z of corners 0, 1, 2 per triangle, in
     * triangle order, NaN for a zero-area triangle (which then fails every comparison of {@link #test})
     * @param mesh the triangles
     */
    public static double[] corners(TriangleMesh mesh) {
        int n = mesh.size();
        double[] c = new double[9 * n];
        for (int t = 0; t < n; t++) {
            for (int k = 0; k < 3; k++) for (int a = 0; a < 3; a++) c[9 * t + 3 * k + a] = mesh.corner(t, k, a);
            if (zeroArea(c, 9 * t)) java.util.Arrays.fill(c, 9 * t, 9 * t + 9, Double.NaN);
        }
        return c;
    }

    /** Exactly whether the three corners at {@code c[b..b+9)} are collinear (or repeated). */
    static boolean zeroArea(double[] c, int b) {
        double e1x = c[b + 3] - c[b], e1y = c[b + 4] - c[b + 1], e1z = c[b + 5] - c[b + 2];
        double e2x = c[b + 6] - c[b], e2y = c[b + 7] - c[b + 1], e2z = c[b + 8] - c[b + 2];
        double nx = e1y * e2z - e1z * e2y, ny = e1z * e2x - e1x * e2z, nz = e1x * e2y - e1y * e2x;
        double scale = 0;
        for (int k = 0; k < 9; k++) scale = Math.max(scale, Math.abs(c[b + k]));
        // Far from zero the double cross product decides; near zero only exact arithmetic can.
        double bound = Tolerance.DEGENERATE_ULPS * Math.ulp(1.0) * 4 * scale * scale;
        if (Math.abs(nx) > bound || Math.abs(ny) > bound || Math.abs(nz) > bound) return false;
        BigDecimal[] p = new BigDecimal[9];
        for (int k = 0; k < 9; k++) p[k] = new BigDecimal(c[b + k]);
        BigDecimal[] e1 = {p[3].subtract(p[0]), p[4].subtract(p[1]), p[5].subtract(p[2])};
        BigDecimal[] e2 = {p[6].subtract(p[0]), p[7].subtract(p[1]), p[8].subtract(p[2])};
        for (int a = 0; a < 3; a++) {
            int a1 = (a + 1) % 3, a2 = (a + 2) % 3;
            if (e1[a1].multiply(e2[a2]).compareTo(e1[a2].multiply(e2[a1])) != 0) return false;
        }
        return true;
    }
}
