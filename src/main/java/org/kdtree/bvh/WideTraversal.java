package org.kdtree.bvh;

import org.kdtree.accel.Hit;
import org.kdtree.accel.RayQuery;
import org.kdtree.accel.TriangleIntersector;
import org.kdtree.accel.Vectorization;
import org.kdtree.geom.Ray;
import org.kdtree.geom.Tolerance;

/**
 * The fast traversal of a {@link Bvh} over a triangle mesh, the one loop for single rays on both
 * paths, over its wide layout ({@link WideNodes}, {@link Bvh#width()} children a node) and its
 * leaf blocks ({@link LeafBlocks}): per node the node kernel ({@link RayKernel#enter}) tests the
 * children's boxes with the ray's near and far planes chosen once per ray; the children entered
 * are pushed farthest first so that the nearest is taken next; a saved entry is dropped when it
 * starts beyond the closest hit; per leaf the leaf kernel ({@link RayKernel#hit}) runs the
 * watertight triangle test. Box intervals are widened by {@link Tolerance#TRAVERSAL_SLACK}, as in
 * every traversal of the project, here as factors on a non-negative interval. Allocation-free per
 * ray; not thread safe: one per thread.
 */
final class WideTraversal implements RayQuery {
    private static final double SLACK = Tolerance.TRAVERSAL_SLACK;
    /** The kernels, chosen once for the JVM: a final static, so that the JIT inlines the one class it holds. */
    static final RayKernel KERNEL = Vectorization.kernel(RayKernel.class, "org.kdtree.bvh.VectorRayKernel", new ScalarRayKernel());

    private final int width, stride;
    private final int[] words, prim, firstBlock;
    private final double[] blocks;
    private final boolean empty;
    /** Saved entries: a wide node's index, or {@code -1 - word} for a leaf child (the word of its reference); where the ray enters it. */
    private final int[] stackEntry;
    private final double[] stackT;
    /** One node's children entered, as the node kernel appends them, sorted by entry distance before they are pushed. */
    private final int[] hitEntry;
    private final double[] hitT;
    private final Hit scratch = new Hit();
    /** Traces the rays this loop leaves out: those with a zero direction component, or a negative tMin. */
    private final BvhTraverser general;

    WideTraversal(Bvh bvh) {
        WideNodes w = bvh.wide();
        width = w.width;
        stride = w.stride;
        words = w.words;
        prim = bvh.primitiveArray();
        LeafBlocks lb = bvh.leafBlocks();
        blocks = lb.coordinates;
        firstBlock = lb.firstBlock;
        empty = bvh.primitiveCount() == 0;
        int stack = (bvh.maxDepth() + 1) * (width - 1) + 2;
        stackEntry = new int[stack];
        stackT = new double[stack];
        hitEntry = new int[width];
        hitT = new double[width + RayKernel.SPARE];
        general = new BvhTraverser(bvh, org.kdtree.accel.TraversalListener.NONE);
    }

    @Override public boolean closestHit(Ray ray, double tMin, double tMax, Hit hit) {
        if (!suits(ray, tMin)) return general.closestHit(ray, tMin, tMax, hit);
        hit.reset();
        int r = trace(ray, tMin, tMax, hit, false);
        if (r < 0) return false;
        hit.primitive = prim[r];     // the test recorded the position in leaf order
        return true;
    }

    @Override public boolean anyHit(Ray ray, double tMin, double tMax) {
        if (!suits(ray, tMin)) return general.anyHit(ray, tMin, tMax);
        return trace(ray, tMin, tMax, scratch.reset(), true) >= 0;
    }

    /**
     * Whether this loop traces the ray: one whose direction has no zero component (so that no
     * slab bound is 0 times infinity, NaN, and the loop needs no test for it) and whose interval
     * starts at t >= 0 (so that the slack can be a factor). Others, rare, take the binary
     * traversal, which handles both.
     */
    static boolean suits(Ray ray, double tMin) {
        return tMin >= 0 && ray.dimension() == 3 && Double.isFinite(ray.inverseDirection(0))
                && Double.isFinite(ray.inverseDirection(1)) && Double.isFinite(ray.inverseDirection(2));
    }

    /**
     * Where box intervals start, for a {@code tMin >= 0} ({@link #suits}): {@code tMin}, or 0 when
     * it is subnormal (the benchmark's tMin is {@link Double#MIN_VALUE}): arithmetic on subnormal
     * numbers takes the processor a hundred cycles per operation, and starting earlier only admits
     * more boxes.
     */
    static double boxStart(double tMin) {
        return tMin >= Double.MIN_NORMAL ? tMin : 0;
    }

    /** Returns the leaf-order position of the closest (or, for {@code any}, the first) hit, or -1. */
    private int trace(Ray ray, double tMin, double tMax, Hit hit, boolean any) {
        ray.requireTraceable(3, "hierarchy");
        if (empty || !(tMin <= tMax)) return -1;
        double ox = ray.origin(0), oy = ray.origin(1), oz = ray.origin(2);
        double ix = ray.inverseDirection(0), iy = ray.inverseDirection(1), iz = ray.inverseDirection(2);
        int w = width;
        // Offsets of the near and far planes within a node, once per ray: per axis, minima first, then maxima.
        int nx = ix < 0 ? w : 0, ny = (iy < 0 ? w : 0) + 2 * w, nz = (iz < 0 ? w : 0) + 4 * w;
        int fx = w - nx, fy = 5 * w - ny, fz = 9 * w - nz;

        // The watertight test's shear, once per ray.
        int kz = TriangleIntersector.maxAxis(ray.direction(0), ray.direction(1), ray.direction(2));
        int kx = kz == 2 ? 0 : kz + 1, ky = kx == 2 ? 0 : kx + 1;
        if (ray.direction(kz) < 0) { int s = kx; kx = ky; ky = s; }
        double sz = ray.inverseDirection(kz), sx = ray.direction(kx) * sz, sy = ray.direction(ky) * sz;
        double okx = ray.origin(kx), oky = ray.origin(ky), okz = ray.origin(kz);

        RayKernel kernel = KERNEL;
        int[] nd = words, se = stackEntry, he = hitEntry;
        double[] st = stackT, ht = hitT;
        int found = -1, sp = 0, e = 0;
        double best = tMax, start = boxStart(tMin);
        while (true) {
            if (e >= 0) {
                // An interior node: the children entered; go on with the nearest, save the others.
                int m = kernel.enter(nd, stride * e, w, nx, fx, ny, fy, nz, fz, ox, oy, oz, ix, iy, iz, start, best + Math.abs(best) * SLACK, he, ht);
                if (m > 0) {
                    sp = saveAllButNearest(he, ht, m, se, st, sp);
                    e = he[m - 1];
                    continue;
                }
            } else {
                int word = -1 - e, from = nd[word];
                int r = kernel.hit(blocks, firstBlock, from, nd[word + w], okx, oky, okz, kx, ky, kz, sx, sy, sz, tMin, best, hit, any);
                if (r >= 0) {
                    if (any) return r;
                    found = r;
                    best = hit.t;
                }
            }
            // The next saved entry that can still hold something closer.
            do {
                if (sp == 0) return found;
                sp--;
            } while (st[sp] > best + Math.abs(best) * SLACK);
            e = se[sp];
        }
    }

    /**
     * Sorts the {@code m} entered children {@code he} (entry distances {@code ht}) farthest first,
     * and pushes all but the nearest (left at {@code he[m - 1]}, taken next) on the stack
     * {@code se}/{@code st} from {@code sp}; returns the new stack size.
     */
    static int saveAllButNearest(int[] he, double[] ht, int m, int[] se, double[] st, int sp) {
        for (int i = 1; i < m; i++) {
            int hi = he[i];
            double ti = ht[i];
            int j = i;
            for (; j > 0 && ht[j - 1] < ti; j--) { he[j] = he[j - 1]; ht[j] = ht[j - 1]; }
            he[j] = hi;
            ht[j] = ti;
        }
        for (int j = 0; j < m - 1; j++) {
            se[sp] = he[j];
            st[sp++] = ht[j];
        }
        return sp;
    }
}
