package org.kdtree.kdtree;

import jdk.incubator.vector.DoubleVector;
import jdk.incubator.vector.VectorMask;
import jdk.incubator.vector.VectorOperators;
import jdk.incubator.vector.VectorSpecies;
import org.kdtree.accel.Hit;

/**
 * The single-ray loop's leaf kernel ({@link RayKernel}) with the Vector API: a leaf's triangles
 * {@link #W} at a time, their corners gathered from the mesh's corners by reference (no copy of
 * the mesh in leaf order: that measured slower, docs/traversal.md). The mailbox is read as the
 * Java 17 kernel reads it, a reference at a time, while the lanes are filled. Each lane does
 * {@link org.kdtree.accel.TriangleIntersector#test}'s operations in its order, without fused
 * multiply-adds, so both kernels give the same answers, bit for bit. Stateless; loaded once by
 * {@link org.kdtree.accel.Vectorization#kernel}.
 */
public final class VectorRayKernel implements RayKernel {
    /** Four triangles a test: a kd-tree's leaves hold about three (the bunny's SAH tree: 2.9). */
    private static final VectorSpecies<Double> B = DoubleVector.SPECIES_256;
    private static final int W = 4;

    /** Made once, by {@link org.kdtree.accel.Vectorization#kernel}. */
    public VectorRayKernel() {
        if (2 * W > LANES) throw new IllegalStateException(W + " lanes need " + 2 * W + " scratch entries");
    }

    @Override public boolean hit(int[] refs, int start, int end, double[] c, int[] lanes, int[] box, int stamp, double okx, double oky,
                                 double okz, int kx, int ky, int kz, double sx, double sy, double sz, double tMin, double tMax, Hit hit,
                                 boolean any) {
        boolean found = false;
        for (int r = start; r < end; ) {
            int n = 0;                                   // lanes[i]: a triangle's first corner; lanes[W + i]: its index
            for (; r < end && n < W; r++) {
                int p = refs[r];
                if (box[p] == stamp) continue;
                box[p] = stamp;
                lanes[n] = 9 * p;
                lanes[W + n++] = p;
            }
            if (n == 0) break;
            for (int i = n; i < W; i++) lanes[i] = lanes[0];     // spare lanes re-read the first triangle, and are masked off
            if (test(c, lanes, n, okx, oky, okz, kx, ky, kz, sx, sy, sz, tMin, tMax, hit)) {
                if (any) return true;
                found = true;
            }
        }
        return found;
    }

    /** The test of the {@code n} triangles whose corners start at {@code lanes[0 .. n)}; {@return whether it recorded a hit} */
    private static boolean test(double[] c, int[] lanes, int n, double okx, double oky, double okz, int kx, int ky, int kz,
                                double sx, double sy, double sz, double tMin, double tMax, Hit hit) {
        DoubleVector az = DoubleVector.fromArray(B, c, kz, lanes, 0).sub(okz);
        DoubleVector bz = DoubleVector.fromArray(B, c, 3 + kz, lanes, 0).sub(okz);
        DoubleVector cz = DoubleVector.fromArray(B, c, 6 + kz, lanes, 0).sub(okz);
        DoubleVector ax = DoubleVector.fromArray(B, c, kx, lanes, 0).sub(okx).sub(az.mul(sx));
        DoubleVector ay = DoubleVector.fromArray(B, c, ky, lanes, 0).sub(oky).sub(az.mul(sy));
        DoubleVector bx = DoubleVector.fromArray(B, c, 3 + kx, lanes, 0).sub(okx).sub(bz.mul(sx));
        DoubleVector by = DoubleVector.fromArray(B, c, 3 + ky, lanes, 0).sub(oky).sub(bz.mul(sy));
        DoubleVector cx = DoubleVector.fromArray(B, c, 6 + kx, lanes, 0).sub(okx).sub(cz.mul(sx));
        DoubleVector cy = DoubleVector.fromArray(B, c, 6 + ky, lanes, 0).sub(oky).sub(cz.mul(sy));
        DoubleVector u = cx.mul(by).sub(cy.mul(bx)), v = ax.mul(cy).sub(ay.mul(cx)), w = bx.mul(ay).sub(by.mul(ax));
        VectorMask<Double> outside = u.lt(0).or(v.lt(0)).or(w.lt(0)).and(u.compare(VectorOperators.GT, 0)
                .or(v.compare(VectorOperators.GT, 0)).or(w.compare(VectorOperators.GT, 0)));
        VectorMask<Double> live = B.indexInRange(0, n);
        if (live.andNot(outside).anyTrue() == false) return false;
        DoubleVector det = u.add(v).add(w);
        DoubleVector t = u.mul(az).add(v.mul(bz)).add(w.mul(cz)).mul(sz).div(det);
        // t <= hit.t here; the tie on a lower index is settled below, a lane at a time.
        long bits = live.andNot(outside).and(det.compare(VectorOperators.NE, 0)).and(t.compare(VectorOperators.GE, tMin))
                .and(t.compare(VectorOperators.LE, tMax)).and(t.compare(VectorOperators.LE, hit.t)).toLong();
        int best = -1;
        double bt = 0;
        for (; bits != 0; bits &= bits - 1) {
            int i = Long.numberOfTrailingZeros(bits);
            double ti = t.lane(i);
            if (best < 0 || ti < bt || ti == bt && lanes[W + i] < lanes[W + best]) { best = i; bt = ti; }
        }
        if (best < 0) return false;
        int prim = lanes[W + best];
        if (!(bt < hit.t || bt == hit.t && prim < hit.primitive)) return false;
        double d = det.lane(best);
        hit.primitive = prim;
        hit.t = bt;
        hit.u = v.lane(best) / d;
        hit.v = w.lane(best) / d;
        return true;
    }
}
