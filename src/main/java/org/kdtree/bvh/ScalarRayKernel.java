package org.kdtree.bvh;

import org.kdtree.accel.Hit;
import org.kdtree.accel.TriangleIntersector;
import org.kdtree.geom.Tolerance;

/** The single-ray loop's kernels in Java 17: one child, one triangle at a time ({@link RayKernel}). */
final class ScalarRayKernel implements RayKernel {
    private static final double SHRINK = 1 - Tolerance.TRAVERSAL_SLACK, GROW = 1 + Tolerance.TRAVERSAL_SLACK;

    @Override public int enter(int[] nd, int base, int w, int nx, int ny, int nz, double ox, double oy, double oz,
                               double ix, double iy, double iz, double start, double limit, int[] entries, double[] t) {
        int fx = base + w - nx, fy = base + 5 * w - ny, fz = base + 9 * w - nz, ref = base + 6 * w, m = 0;
        nx += base;
        ny += base;
        nz += base;
        for (int i = 0; i < w; i++) {
            int count = nd[ref + w + i];
            if (count < 0) break;   // unused slots come last
            // Branch-free slabs: with no zero direction component no bound is NaN.
            double t0 = Math.max(start, (Float.intBitsToFloat(nd[nx + i]) - ox) * ix);
            double t1 = Math.min(limit, (Float.intBitsToFloat(nd[fx + i]) - ox) * ix);
            t0 = Math.max(t0, (Float.intBitsToFloat(nd[ny + i]) - oy) * iy);
            t1 = Math.min(t1, (Float.intBitsToFloat(nd[fy + i]) - oy) * iy);
            t0 = Math.max(t0, (Float.intBitsToFloat(nd[nz + i]) - oz) * iz);
            t1 = Math.min(t1, (Float.intBitsToFloat(nd[fz + i]) - oz) * iz);
            // Appended always, kept only if entered: no branch to mispredict.
            entries[m] = count > 0 ? -1 - (ref + i) : nd[ref + i];
            t[m] = t0;
            m += t0 * SHRINK <= t1 * GROW ? 1 : 0;
        }
        return m;
    }

    /** {@return {@code asked}: {@code --bvh-width} as given} */
    @Override public int width(int asked) { return asked; }

    /** {@return 1: the corners in leaf order, 9 doubles a triangle} */
    @Override public int blockWidth() { return 1; }

    @Override public int hit(double[] c, int[] firstBlock, int first, int count, double okx, double oky, double okz, int kx, int ky, int kz,
                             double sx, double sy, double sz, double tMin, double tMax, Hit hit, boolean any) {
        int found = -1;
        double best = tMax;
        for (int i = 0; i < count; i++) {
            if (TriangleIntersector.test(c, 9 * (first + i), first + i, okx, oky, okz, kx, ky, kz, sx, sy, sz, tMin, best, hit)) {
                if (any) return first + i;
                found = first + i;
                best = hit.t;
            }
        }
        return found;
    }
}
