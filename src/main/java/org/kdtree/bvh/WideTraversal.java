package org.kdtree.bvh;

import org.kdtree.geom.Ray;
import org.kdtree.geom.Tolerance;
import org.kdtree.traverse.Hit;
import org.kdtree.traverse.RayQuery;
import org.kdtree.traverse.TriangleIntersector;

/**
 * The fast traversal of a {@link Bvh} over a triangle mesh: its wide layout ({@link WideNodes}),
 * one node's child boxes tested in one loop with the ray's near and far planes chosen once per
 * ray, the children entered pushed farthest first so that the nearest is taken next, a saved
 * entry dropped when it starts beyond the closest hit, and the one watertight triangle test
 * ({@link TriangleIntersector#test}). Box intervals are widened by
 * {@link Tolerance#TRAVERSAL_SLACK}, as in every traversal of the project. Allocation-free per
 * ray; not thread safe: one per thread.
 */
final class WideTraversal implements RayQuery {
    private static final double SLACK = Tolerance.TRAVERSAL_SLACK;

    private final int width;
    private final double[] box;
    private final int[] ref, count, prim;
    private final double[] corners;
    private final boolean empty;
    /** Saved entries: a wide node's index, or {@code -1 - slot} for a leaf child; and where the ray enters it. */
    private final int[] stackEntry;
    private final double[] stackT;
    /** One node's children entered, sorted by entry distance before they are pushed. */
    private final int[] hitEntry;
    private final double[] hitT;
    private final Hit scratch = new Hit();

    WideTraversal(Bvh bvh, TriangleIntersector tris) {
        WideNodes w = bvh.wide();
        width = w.width;
        box = w.box;
        ref = w.ref;
        count = w.count;
        prim = bvh.primitiveArray();
        corners = tris.cornerArray();
        empty = bvh.primitiveCount() == 0;
        int stack = (bvh.maxDepth() + 1) * (width - 1) + 2;
        stackEntry = new int[stack];
        stackT = new double[stack];
        hitEntry = new int[width];
        hitT = new double[width];
    }

    @Override public boolean closestHit(Ray ray, double tMin, double tMax, Hit hit) {
        hit.reset();
        return trace(ray, tMin, tMax, hit, false);
    }

    @Override public boolean anyHit(Ray ray, double tMin, double tMax) {
        return trace(ray, tMin, tMax, scratch.reset(), true);
    }

    private boolean trace(Ray ray, double tMin, double tMax, Hit hit, boolean any) {
        ray.requireTraceable(3, "hierarchy");
        if (empty || !(tMin <= tMax)) return false;
        double ox = ray.origin(0), oy = ray.origin(1), oz = ray.origin(2);
        double ix = ray.inverseDirection(0), iy = ray.inverseDirection(1), iz = ray.inverseDirection(2);
        int w = width;
        // Offsets of the near and far planes within a node's block of one axis: minima first, then maxima.
        int nx = ix < 0 ? w : 0, ny = (iy < 0 ? w : 0) + 2 * w, nz = (iz < 0 ? w : 0) + 4 * w;
        int fx = w - nx, fy = 5 * w - ny, fz = 9 * w - nz;

        // The watertight test's shear, once per ray.
        int kz = TriangleIntersector.maxAxis(ray.direction(0), ray.direction(1), ray.direction(2));
        int kx = kz == 2 ? 0 : kz + 1, ky = kx == 2 ? 0 : kx + 1;
        if (ray.direction(kz) < 0) { int s = kx; kx = ky; ky = s; }
        double sz = ray.inverseDirection(kz), sx = ray.direction(kx) * sz, sy = ray.direction(ky) * sz;
        double okx = ray.origin(kx), oky = ray.origin(ky), okz = ray.origin(kz);

        double[] b = box, c = corners;
        int[] cnt = count, rf = ref, pr = prim, se = stackEntry, he = hitEntry;
        double[] st = stackT, ht = hitT;
        boolean found = false;
        double best = tMax;
        int sp = 1;
        se[0] = 0;
        st[0] = tMin;
        while (sp > 0) {
            sp--;
            if (st[sp] > best + Math.abs(best) * SLACK) continue;
            int e = se[sp];
            if (e < 0) {
                int slot = -1 - e;
                for (int r = rf[slot], end = r + cnt[slot]; r < end; r++) {
                    int p = pr[r];
                    if (TriangleIntersector.test(c, 9 * p, p, okx, oky, okz, kx, ky, kz, sx, sy, sz, tMin, best, hit)) {
                        if (any) return true;
                        found = true;
                        best = hit.t;
                    }
                }
                continue;
            }
            int base = 6 * w * e, slot0 = w * e, m = 0;
            double limit = best + Math.abs(best) * SLACK;
            for (int i = 0; i < w; i++) {
                int n = cnt[slot0 + i];
                if (n < 0) break;
                double t0 = tMin, t1 = limit, a;
                a = (b[base + nx + i] - ox) * ix; if (a > t0) t0 = a;
                a = (b[base + fx + i] - ox) * ix; if (a < t1) t1 = a;
                a = (b[base + ny + i] - oy) * iy; if (a > t0) t0 = a;
                a = (b[base + fy + i] - oy) * iy; if (a < t1) t1 = a;
                a = (b[base + nz + i] - oz) * iz; if (a > t0) t0 = a;
                a = (b[base + fz + i] - oz) * iz; if (a < t1) t1 = a;
                if (!(t0 - Math.abs(t0) * SLACK <= t1 + Math.abs(t1) * SLACK)) continue; // NaN: an infinite bound, missed
                // Insert by entry distance, farthest first.
                int j = m++;
                while (j > 0 && ht[j - 1] < t0) { he[j] = he[j - 1]; ht[j] = ht[j - 1]; j--; }
                he[j] = n > 0 ? -1 - (slot0 + i) : rf[slot0 + i];
                ht[j] = t0;
            }
            for (int j = 0; j < m; j++) {
                se[sp] = he[j];
                st[sp++] = ht[j];
            }
        }
        return found;
    }
}
