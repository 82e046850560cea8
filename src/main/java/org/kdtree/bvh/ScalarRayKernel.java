package org.kdtree.bvh;

import org.kdtree.accel.Hit;
import org.kdtree.accel.TriangleIntersector;
import org.kdtree.geom.Tolerance;

/** The single-ray loop's kernels in Java 17: one child, one triangle at a time ({@link RayKernel}). */
final class ScalarRayKernel implements RayKernel {
    private static final double SHRINK = 1 - Tolerance.TRAVERSAL_SLACK, GROW = 1 + Tolerance.TRAVERSAL_SLACK;

    @Override public int enter(int[] nd, int base, int w, int nx, int fx, int ny, int fy, int nz, int fz, double ox, double oy, double oz,
                               double ix, double iy, double iz, double start, double limit, int[] entries, double[] t) {
        int m = 0;
        for (int i = 0, at = base, ref = base + 6 * w; i < w; i++, at++, ref++) {
            int count = nd[ref + w];
            if (count < 0) break;   // unused slots come last
            // Branch-free slabs: with no zero direction component no bound is NaN.
            double t0 = Math.max(start, (Float.intBitsToFloat(nd[at + nx]) - ox) * ix);
            double t1 = Math.min(limit, (Float.intBitsToFloat(nd[at + fx]) - ox) * ix);
            t0 = Math.max(t0, (Float.intBitsToFloat(nd[at + ny]) - oy) * iy);
            t1 = Math.min(t1, (Float.intBitsToFloat(nd[at + fy]) - oy) * iy);
            t0 = Math.max(t0, (Float.intBitsToFloat(nd[at + nz]) - oz) * iz);
            t1 = Math.min(t1, (Float.intBitsToFloat(nd[at + fz]) - oz) * iz);
            // Appended always, kept only if entered: no branch to mispredict.
            entries[m] = count > 0 ? -1 - ref : nd[ref];
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
