package org.kdtree.bvh;

import org.kdtree.accel.Hit;
import org.kdtree.accel.RayQuery;
import org.kdtree.accel.TraversalListener;
import org.kdtree.accel.TriangleIntersector;
import org.kdtree.geom.Ray;
import org.kdtree.geom.Tolerance;

/**
 * The scalar fast traversal of a 3-D {@link Bvh} over a triangle mesh, on its compact binary
 * layout ({@link PairNodes}: one cache line per node with both children's boxes). At each node
 * both children's slabs are tested from that one record, with the near and far planes of each
 * axis picked once per ray by the direction's signs; the near child (smaller entry distance) is
 * taken next and the far one saved with its entry distance, so that a saved child that starts
 * beyond the closest hit is dropped when it is popped. Intervals combine with plain compares
 * (no {@code Math.max}/{@code min}: with no NaN bound and t &gt;= 0 a compare is exact, and
 * cheaper). Leaves test their triangles from the corners in leaf order
 * ({@link Bvh#leafCorners}) with the watertight test ({@link TriangleIntersector#test}).
 *
 * <p>Box intervals are widened by {@link Tolerance#TRAVERSAL_SLACK} as factors on a
 * non-negative interval, as in {@link WideTraversal}; rays with a zero direction component or a
 * negative tMin take the binary traversal ({@link BvhTraverser}), which handles both.
 * Allocation-free per ray; not thread safe: one per thread.
 */
final class PairTraversal implements RayQuery {
    private static final double SLACK = Tolerance.TRAVERSAL_SLACK;
    private static final double SHRINK = 1 - SLACK, GROW = 1 + SLACK;
    private static final int STRIDE = PairNodes.STRIDE, RIGHT = PairNodes.RIGHT, LINKS = PairNodes.LINKS;

    private final int[] words, prim;
    private final double[] corners;
    private final boolean empty;
    /** Saved children: a record's index, or {@code -1 - word} for a leaf (the word of its reference); where the ray enters it. */
    private final int[] stackEntry;
    private final double[] stackT;
    private final Hit scratch = new Hit();
    private final BvhTraverser general;

    PairTraversal(Bvh bvh) {
        words = bvh.pairs().words;
        prim = bvh.primitiveArray();
        corners = bvh.leafCorners();
        empty = bvh.primitiveCount() == 0;
        stackEntry = new int[bvh.maxDepth() + 2];
        stackT = new double[bvh.maxDepth() + 2];
        general = new BvhTraverser(bvh, TraversalListener.NONE);
    }

    @Override public boolean closestHit(Ray ray, double tMin, double tMax, Hit hit) {
        if (!WideTraversal.suits(ray, tMin)) return general.closestHit(ray, tMin, tMax, hit);
        hit.reset();
        int r = trace(ray, tMin, tMax, hit, false);
        if (r < 0) return false;
        hit.primitive = prim[r];
        return true;
    }

    @Override public boolean anyHit(Ray ray, double tMin, double tMax) {
        if (!WideTraversal.suits(ray, tMin)) return general.anyHit(ray, tMin, tMax);
        return trace(ray, tMin, tMax, scratch.reset(), true) >= 0;
    }

    /** Returns the leaf-order position of the closest (or, for {@code any}, the first) hit, or -1. */
    private int trace(Ray ray, double tMin, double tMax, Hit hit, boolean any) {
        ray.requireTraceable(3, "hierarchy");
        if (empty || !(tMin <= tMax)) return -1;
        double ox = ray.origin(0), oy = ray.origin(1), oz = ray.origin(2);
        double ix = ray.inverseDirection(0), iy = ray.inverseDirection(1), iz = ray.inverseDirection(2);
        // Within a child's six words: its near plane on each axis (the min if the ray runs up the axis), and its far plane.
        int nx = ix < 0 ? 3 : 0, ny = iy < 0 ? 4 : 1, nz = iz < 0 ? 5 : 2;
        int fx = 3 - nx, fy = 5 - ny, fz = 7 - nz;

        int kz = TriangleIntersector.maxAxis(ray.direction(0), ray.direction(1), ray.direction(2));
        int kx = kz == 2 ? 0 : kz + 1, ky = kx == 2 ? 0 : kx + 1;
        if (ray.direction(kz) < 0) { int s = kx; kx = ky; ky = s; }
        double sz = ray.inverseDirection(kz), sx = ray.direction(kx) * sz, sy = ray.direction(ky) * sz;
        double okx = ray.origin(kx), oky = ray.origin(ky), okz = ray.origin(kz);

        int[] nd = words, se = stackEntry;
        double[] c = corners, st = stackT;
        int found = -1, sp = 0, e = 0;
        double best = tMax, start = WideTraversal.boxStart(tMin), limit = best + Math.abs(best) * SLACK;
        while (true) {
            if (e >= 0) {
                int l = STRIDE * e, r = l + RIGHT;
                double l0 = (Float.intBitsToFloat(nd[l + nx]) - ox) * ix, l1 = (Float.intBitsToFloat(nd[l + fx]) - ox) * ix;
                double r0 = (Float.intBitsToFloat(nd[r + nx]) - ox) * ix, r1 = (Float.intBitsToFloat(nd[r + fx]) - ox) * ix;
                double a, b;
                a = (Float.intBitsToFloat(nd[l + ny]) - oy) * iy; l0 = Math.max(l0, a);
                b = (Float.intBitsToFloat(nd[l + fy]) - oy) * iy; l1 = Math.min(l1, b);
                a = (Float.intBitsToFloat(nd[r + ny]) - oy) * iy; r0 = Math.max(r0, a);
                b = (Float.intBitsToFloat(nd[r + fy]) - oy) * iy; r1 = Math.min(r1, b);
                a = (Float.intBitsToFloat(nd[l + nz]) - oz) * iz; l0 = Math.max(l0, a);
                b = (Float.intBitsToFloat(nd[l + fz]) - oz) * iz; l1 = Math.min(l1, b);
                a = (Float.intBitsToFloat(nd[r + nz]) - oz) * iz; r0 = Math.max(r0, a);
                b = (Float.intBitsToFloat(nd[r + fz]) - oz) * iz; r1 = Math.min(r1, b);
                l0 = Math.max(l0, start);
                r0 = Math.max(r0, start);
                l1 = Math.min(l1, limit);
                r1 = Math.min(r1, limit);
                boolean inL = l0 * SHRINK <= l1 * GROW, inR = r0 * SHRINK <= r1 * GROW;
                // Without branches to mispredict on incoherent rays: the child to take (the near one
                // if both are entered) and the other, saved always but kept only if both are entered.
                int link = STRIDE * e + LINKS;
                boolean rightFirst = inR & (!inL | r0 < l0);
                int first = rightFirst ? link + 2 : link, second = rightFirst ? link : link + 2;
                se[sp] = PairNodes.code(nd, second);
                st[sp] = rightFirst ? l0 : r0;
                sp += inL & inR ? 1 : 0;
                if (inL | inR) {
                    e = PairNodes.code(nd, first);
                    continue;
                }
            } else {
                int word = -1 - e;
                for (int r = nd[word], end = r + nd[word + 1]; r < end; r++) {
                    if (TriangleIntersector.test(c, 9 * r, r, okx, oky, okz, kx, ky, kz, sx, sy, sz, tMin, best, hit)) {
                        if (any) return r;
                        found = r;
                        best = hit.t;
                        limit = best + Math.abs(best) * SLACK;
                    }
                }
            }
            // The next saved child that can still hold something closer.
            do {
                if (sp == 0) return found;
                sp--;
            } while (st[sp] > limit);
            e = se[sp];
        }
    }
}
