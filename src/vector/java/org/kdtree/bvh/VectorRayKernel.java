package org.kdtree.bvh;

import jdk.incubator.vector.DoubleVector;
import jdk.incubator.vector.IntVector;
import jdk.incubator.vector.VectorMask;
import jdk.incubator.vector.VectorOperators;
import jdk.incubator.vector.VectorShape;
import jdk.incubator.vector.VectorSpecies;
import org.kdtree.accel.Hit;
import org.kdtree.geom.Tolerance;

/**
 * The single-ray loop's kernels ({@link RayKernel}) with the Vector API: a wide node's children's
 * boxes as many at once as the machine's double lanes ({@link DoubleVector#SPECIES_PREFERRED}: 8
 * with AVX-512, 4 with AVX2; a node wider than that in several steps, a narrower one with the
 * lanes past its width ignored), and a leaf's triangles four at a time from their blocks
 * ({@link LeafBlocks} of width 4). Each lane does exactly the Java 17 kernel's operations in the
 * same order, in double precision on the same float planes, so both give the same answers, bit for
 * bit. Compiled for JDK 21 with {@code jdk.incubator.vector} (src/vector/java) and loaded only
 * through {@link org.kdtree.accel.Vectorization#kernel}. Allocation-free (the vectors are
 * scalar-replaced by C2).
 */
public final class VectorRayKernel implements RayKernel {
    private static final VectorSpecies<Double> S = DoubleVector.SPECIES_PREFERRED;
    private static final int L = S.length();
    /** As many ints (the boxes' float bits) as {@link #S} has double lanes. */
    private static final VectorSpecies<Integer> I = VectorSpecies.of(int.class, VectorShape.forBitSize(S.vectorBitSize() / 2));
    /** A leaf's triangles, {@link #W} at a time. */
    private static final VectorSpecies<Double> B = DoubleVector.SPECIES_256;
    private static final int W = 4;
    /** 0, 1, 2, 3: a block's lanes' offsets from its first position. */
    private static final DoubleVector LANE = DoubleVector.fromArray(B, new double[] {0, 1, 2, 3}, 0);
    private static final double SHRINK = 1 - Tolerance.TRAVERSAL_SLACK, GROW = 1 + Tolerance.TRAVERSAL_SLACK;

    /** The kernels; made by {@link org.kdtree.accel.Vectorization#kernel}. */
    public VectorRayKernel() {
        if (L > RayKernel.SPARE) throw new IllegalStateException(L + " lanes exceed the spare entries of a node");
    }

    /** The children's planes at {@code words[at .. at + lanes)}: their float bits, widened exactly to doubles. */
    private static DoubleVector planes(int[] words, int at) {
        return (DoubleVector) IntVector.fromArray(I, words, at).reinterpretAsFloats().convertShape(VectorOperators.F2D, S, 0);
    }

    @Override public int enter(int[] nd, int base, int w, int nx, int fx, int ny, int fy, int nz, int fz, double ox, double oy, double oz,
                               double ix, double iy, double iz, double start, double limit, int[] entries, double[] t) {
        int m = 0;
        for (int i = 0; i < w; i += L) {
            int at = base + i;
            DoubleVector t0 = planes(nd, at + nx).sub(ox).mul(ix).max(start);
            DoubleVector t1 = planes(nd, at + fx).sub(ox).mul(ix).min(limit);
            t0 = t0.max(planes(nd, at + ny).sub(oy).mul(iy));
            t1 = t1.min(planes(nd, at + fy).sub(oy).mul(iy));
            t0 = t0.max(planes(nd, at + nz).sub(oz).mul(iz));
            t1 = t1.min(planes(nd, at + fz).sub(oz).mul(iz));
            // Lanes past the node's width read the next rows: ignored.
            int in = (int) t0.mul(SHRINK).compare(VectorOperators.LE, t1.mul(GROW)).toLong() & (1 << w - i) - 1;
            if (in == 0) continue;
            t0.intoArray(t, m);
            m = append(nd, at + 6 * w, w, in, m, entries, t);
        }
        return m;
    }

    /**
     * Appends the lanes {@code in} of the slots from {@code slot} whose entry distances stand in
     * {@code t} from {@code m}: each moved down to the next place (never past its own lane), in slot
     * order as the Java 17 kernel appends them; only the entered lanes are visited. A method of its
     * own so that {@link #enter} stays small enough for C2 to inline.
     */
    private static int append(int[] nd, int slot, int w, int in, int m, int[] entries, double[] t) {
        for (int from = m; in != 0; in &= in - 1) {
            int j = Integer.numberOfTrailingZeros(in), s = slot + j;
            entries[m] = nd[s + w] > 0 ? -1 - s : nd[s];
            t[m++] = t[from + j];
        }
        return m;
    }

    /** {@return the lanes (within the widths allowed, 2 to 8)}: on the grid mesh of bvh.md, 8-wide nodes ran R at 1.3 x the 4-wide ones */
    @Override public int width(int asked) { return Math.max(2, Math.min(8, L)); }

    /** {@return 4: a leaf's triangles four to a block, a 256-bit vector per coordinate} */
    @Override public int blockWidth() { return W; }

    /**
     * The watertight test of the leaf's triangles a block of four at a time (leaf positions from
     * {@code first}): each lane {@link org.kdtree.accel.TriangleIntersector#test}'s operations in
     * its order. Of a block's lanes that hit within {@code [tMin, best]} and closer than {@code hit}
     * (or as close, at a lower position), the closest, of equals the first, is recorded in {@code
     * hit}: what testing them one after the other records. One method for the whole leaf, so that
     * the loop makes one call a leaf (a block's test is too big for C2 to inline).
     */
    @Override public int hit(double[] c, int[] firstBlock, int first, int count, double okx, double oky, double okz, int kx, int ky, int kz,
                             double sx, double sy, double sz, double tMin, double tMax, Hit hit, boolean any) {
        int found = -1;
        double best = tMax;
        for (int k = 0, block = firstBlock[first]; k < count; k += W, block++) {
            int o = 9 * W * block, at = first + k;
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
            if (outside.allTrue()) continue;
            DoubleVector det = u.add(v).add(w);
            DoubleVector t = u.mul(az).add(v.mul(bz)).add(w.mul(cz)).mul(sz).div(det);
            double hitT = hit.t;
            VectorMask<Double> ok = outside.not().and(det.compare(VectorOperators.NE, 0)).and(t.compare(VectorOperators.GE, tMin))
                    .and(t.compare(VectorOperators.LE, best))
                    .and(t.lt(hitT).or(t.eq(hitT).and(LANE.add(at).lt(hit.primitive))));
            long bits = ok.toLong();
            if (bits == 0) continue;
            // The closest of the lanes that hit, of equals the lowest: the one the one-by-one loop keeps.
            int lane = Long.numberOfTrailingZeros(bits);
            double bt = t.lane(lane);
            for (bits &= bits - 1; bits != 0; bits &= bits - 1) {
                int i = Long.numberOfTrailingZeros(bits);
                double ti = t.lane(i);
                if (ti < bt) { lane = i; bt = ti; }
            }
            double d = det.lane(lane);
            hit.primitive = at + lane;
            hit.t = bt;
            hit.u = v.lane(lane) / d;
            hit.v = w.lane(lane) / d;
            if (any) return at + lane;
            found = at + lane;
            best = bt;
        }
        return found;
    }
}
