package org.kdtree.bvh;

import jdk.incubator.vector.DoubleVector;
import jdk.incubator.vector.IntVector;
import jdk.incubator.vector.VectorMask;
import jdk.incubator.vector.VectorOperators;
import jdk.incubator.vector.VectorShape;
import jdk.incubator.vector.VectorSpecies;
import org.kdtree.accel.Hit;
import org.kdtree.accel.RayQuery;
import org.kdtree.accel.TraversalListener;
import org.kdtree.accel.TriangleIntersector;
import org.kdtree.geom.Ray;
import org.kdtree.geom.Tolerance;

/**
 * {@link WideTraversal} with the Vector API: a wide node's children's boxes, as many as the
 * machine's double lanes ({@link DoubleVector#SPECIES_PREFERRED}: 8 with AVX-512, 4 with AVX2),
 * tested at once. Each lane does exactly the scalar loop's operations in the same order, in
 * double precision on the same rounded-outward boxes ({@link WideNodes#boxesAsDoubles}): the
 * slab distances {@code (plane - o) * inv}, their maximum and minimum with the interval, and
 * {@code t0 (1 - slack) <= t1 (1 + slack)}; so it enters the children the scalar loop enters,
 * sorts them the same way and finds the same hits, bit for bit. A leaf's triangles are tested
 * {@link LeafBlocks#WIDTH} at a time from its blocks ({@link #testBlock}), each lane the one
 * watertight test.
 *
 * <p>Compiled for JDK 21 with {@code jdk.incubator.vector} (src/vector/java) and loaded only
 * through {@link VectorPath}. Allocation-free per ray (the vectors are scalar-replaced by C2);
 * not thread safe: one per thread.
 */
final class VectorTraversal implements RayQuery {
    private static final VectorSpecies<Double> S = DoubleVector.SPECIES_PREFERRED;
    /** A leaf's triangles, {@link LeafBlocks#WIDTH} at a time. */
    private static final VectorSpecies<Double> B = DoubleVector.SPECIES_256;
    /** 0, 1, 2, 3: a block's lanes' offsets from its first position. */
    private static final DoubleVector LANE = DoubleVector.fromArray(B, new double[] {0, 1, 2, 3}, 0);
    /** As many ints (the boxes' float bits) as {@link #S} has double lanes. */
    private static final VectorSpecies<Integer> I = VectorSpecies.of(int.class, VectorShape.forBitSize(S.vectorBitSize() / 2));
    private static final double SLACK = Tolerance.TRAVERSAL_SLACK;
    private static final double SHRINK = 1 - SLACK, GROW = 1 + SLACK;

    private final int width, stride, refs;
    private final int[] words, prim;
    /** The leaves' triangles in blocks ({@link LeafBlocks}). */
    private final double[] blocks;
    private final int[] firstBlock;
    private final boolean empty;
    private final int[] stackEntry;
    private final double[] stackT;
    private final int[] hitEntry;
    private final double[] hitT, lane;
    private final Hit scratch = new Hit();
    private final BvhTraverser general;

    /** {@return the children tested at once: the lanes of the machine's preferred double vector} */
    static int lanes() {
        return S.length();
    }

    VectorTraversal(Bvh bvh) {
        WideNodes w = bvh.lanes(S.length());
        width = w.width;
        stride = w.stride;
        refs = w.refs;
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
        hitT = new double[width];
        lane = new double[width];
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

    /** The children's planes at {@code words[at .. at + lanes)}: their float bits, widened exactly to doubles. */
    private static DoubleVector planes(int[] words, int at) {
        return (DoubleVector) IntVector.fromArray(I, words, at).reinterpretAsFloats().convertShape(VectorOperators.F2D, S, 0);
    }

    /**
     * The watertight test of a block's {@link LeafBlocks#WIDTH} triangles (leaf positions from
     * {@code first}) at once: each lane {@link TriangleIntersector#test}'s operations in its order.
     * Of the lanes that hit within {@code [tMin, tMax]} and closer than {@code hit} (or as close,
     * at a lower position), the closest, of equals the first, is recorded in {@code hit}: what
     * testing them one after the other records. Returns its leaf position, or -1.
     */
    private int testBlock(int block, int first, double okx, double oky, double okz, int kx, int ky, int kz,
                          double sx, double sy, double sz, double tMin, double tMax, Hit hit) {
        double[] c = blocks;
        int o = LeafBlocks.STRIDE * block, W = LeafBlocks.WIDTH;
        DoubleVector az = DoubleVector.fromArray(B, c, o + W * kz).sub(okz);
        DoubleVector bz = DoubleVector.fromArray(B, c, o + W * (3 + kz)).sub(okz);
        DoubleVector cz = DoubleVector.fromArray(B, c, o + W * (6 + kz)).sub(okz);
        DoubleVector ax = DoubleVector.fromArray(B, c, o + W * kx).sub(okx).sub(az.mul(sx));
        DoubleVector ay = DoubleVector.fromArray(B, c, o + W * ky).sub(oky).sub(az.mul(sy));
        DoubleVector bx = DoubleVector.fromArray(B, c, o + W * (3 + kx)).sub(okx).sub(bz.mul(sx));
        DoubleVector by = DoubleVector.fromArray(B, c, o + W * (3 + ky)).sub(oky).sub(bz.mul(sy));
        DoubleVector cx = DoubleVector.fromArray(B, c, o + W * (6 + kx)).sub(okx).sub(cz.mul(sx));
        DoubleVector cy = DoubleVector.fromArray(B, c, o + W * (6 + ky)).sub(oky).sub(cz.mul(sy));
        DoubleVector u = cx.mul(by).sub(cy.mul(bx)), v = ax.mul(cy).sub(ay.mul(cx)), w = bx.mul(ay).sub(by.mul(ax));
        VectorMask<Double> outside = u.lt(0).or(v.lt(0)).or(w.lt(0)).and(u.compare(VectorOperators.GT, 0)
                .or(v.compare(VectorOperators.GT, 0)).or(w.compare(VectorOperators.GT, 0)));
        if (outside.allTrue()) return -1;
        DoubleVector det = u.add(v).add(w);
        DoubleVector t = u.mul(az).add(v.mul(bz)).add(w.mul(cz)).mul(sz).div(det);
        double hitT = hit.t;
        VectorMask<Double> ok = outside.not().and(det.compare(VectorOperators.NE, 0)).and(t.compare(VectorOperators.GE, tMin))
                .and(t.compare(VectorOperators.LE, tMax))
                .and(t.lt(hitT).or(t.eq(hitT).and(LANE.add(first).lt(hit.primitive))));
        long bits = ok.toLong();
        if (bits == 0) return -1;
        // The closest of the lanes that hit, of equals the lowest: the one the one-by-one loop keeps.
        int best = Long.numberOfTrailingZeros(bits);
        double bt = t.lane(best);
        for (bits &= bits - 1; bits != 0; bits &= bits - 1) {
            int i = Long.numberOfTrailingZeros(bits);
            double ti = t.lane(i);
            if (ti < bt) { best = i; bt = ti; }
        }
        double d = det.lane(best);
        hit.primitive = first + best;
        hit.t = bt;
        hit.u = v.lane(best) / d;
        hit.v = w.lane(best) / d;
        return first + best;
    }

    private int trace(Ray ray, double tMin, double tMax, Hit hit, boolean any) {
        ray.requireTraceable(3, "hierarchy");
        if (empty || !(tMin <= tMax)) return -1;
        double ox = ray.origin(0), oy = ray.origin(1), oz = ray.origin(2);
        double ix = ray.inverseDirection(0), iy = ray.inverseDirection(1), iz = ray.inverseDirection(2);
        int w = width;
        // Offsets of the near and far planes within a node's boxes: per axis, minima first, then maxima.
        int nx = ix < 0 ? w : 0, ny = (iy < 0 ? w : 0) + 2 * w, nz = (iz < 0 ? w : 0) + 4 * w;
        int fx = w - nx, fy = 5 * w - ny, fz = 9 * w - nz;

        int kz = TriangleIntersector.maxAxis(ray.direction(0), ray.direction(1), ray.direction(2));
        int kx = kz == 2 ? 0 : kz + 1, ky = kx == 2 ? 0 : kx + 1;
        if (ray.direction(kz) < 0) { int s = kx; kx = ky; ky = s; }
        double sz = ray.inverseDirection(kz), sx = ray.direction(kx) * sz, sy = ray.direction(ky) * sz;
        double okx = ray.origin(kx), oky = ray.origin(ky), okz = ray.origin(kz);

        int[] nd = words, se = stackEntry, he = hitEntry;
        double[] st = stackT, ht = hitT, tl = lane;
        int found = -1, sp = 0, e = 0;
        double best = tMax, start = WideTraversal.boxStart(tMin);
        while (true) {
            if (e >= 0) {
                int base = stride * e;
                double limit = best + Math.abs(best) * SLACK;
                DoubleVector t0 = planes(nd, base + nx).sub(ox).mul(ix).max(start);
                DoubleVector t1 = planes(nd, base + fx).sub(ox).mul(ix).min(limit);
                t0 = t0.max(planes(nd, base + ny).sub(oy).mul(iy));
                t1 = t1.min(planes(nd, base + fy).sub(oy).mul(iy));
                t0 = t0.max(planes(nd, base + nz).sub(oz).mul(iz));
                t1 = t1.min(planes(nd, base + fz).sub(oz).mul(iz));
                VectorMask<Double> in = t0.mul(SHRINK).compare(VectorOperators.LE, t1.mul(GROW));
                long bits = in.toLong();
                int m = 0;
                if (bits != 0) {
                    t0.intoArray(tl, 0);
                    for (; bits != 0; bits &= bits - 1) {
                        int i = Long.numberOfTrailingZeros(bits);
                        he[m] = nd[base + refs + w + i] > 0 ? -1 - (base + refs + i) : nd[base + refs + i];
                        ht[m++] = tl[i];
                    }
                }
                if (m > 0) {
                    sp = WideTraversal.saveAllButNearest(he, ht, m, se, st, sp);
                    e = he[m - 1];
                    continue;
                }
            } else {
                int word = -1 - e, from = nd[word], count = nd[word + w];
                for (int k = 0, block = firstBlock[from]; k < count; k += LeafBlocks.WIDTH, block++) {
                    int r = testBlock(block, from + k, okx, oky, okz, kx, ky, kz, sx, sy, sz, tMin, best, hit);
                    if (r >= 0) {
                        if (any) return r;
                        found = r;
                        best = hit.t;
                    }
                }
            }
            do {
                if (sp == 0) return found;
                sp--;
            } while (st[sp] > best + Math.abs(best) * SLACK);
            e = se[sp];
        }
    }
}
