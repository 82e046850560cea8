package org.kdtree.kdtree;

import jdk.incubator.vector.DoubleVector;
import jdk.incubator.vector.VectorMask;
import jdk.incubator.vector.VectorOperators;
import jdk.incubator.vector.VectorSpecies;

/**
 * The packet loop's kernels with the Vector API: the lanes of a packet a group of {@link #L} at a
 * time (this machine's widest double vector: 8 with AVX-512, 4 with AVX2), groups with no active
 * lane skipped. Each lane does {@link ScalarPacketKernel}'s operations in the same order, lane-wise
 * and without fused multiply-adds, so its results are the same bit for bit; a lane's shear axes,
 * which may differ from lane to lane, select its corner coordinates by blends. Stateless; loaded
 * once by {@link org.kdtree.accel.Vectorization#kernel}.
 */
public final class VectorPacketKernel implements PacketKernel {
    private static final VectorSpecies<Double> D = DoubleVector.SPECIES_PREFERRED;
    private static final int L = D.length();
    private static final long GROUP = L == 64 ? -1L : (1L << L) - 1;
    private static final double SLACK = Traverser.SLACK;

    /** Made once, by {@link org.kdtree.accel.Vectorization#kernel}. */
    public VectorPacketKernel() {
        if (PacketLanes.N % L != 0) throw new IllegalStateException(PacketLanes.N + " lanes are not groups of " + L);
    }

    @Override
    public void node(PacketLanes lanes, long active, int axis, double plane, double[] farMin, double[] farMax, int at) {
        double[] o = lanes.origin[axis], iv = lanes.inverse[axis];
        long toNear = 0, toFar = 0;
        DoubleVector p = DoubleVector.broadcast(D, plane);
        for (int g = 0; g < PacketLanes.N; g += L) {
            long bits = active >>> g & GROUP;
            if (bits == 0) continue;
            VectorMask<Double> on = VectorMask.fromLong(D, bits);
            DoubleVector t = p.sub(DoubleVector.fromArray(D, o, g)).mul(DoubleVector.fromArray(D, iv, g));
            DoubleVector hi = DoubleVector.fromArray(D, lanes.hi, g), curMax = DoubleVector.fromArray(D, lanes.curMax, g);
            VectorMask<Double> near = t.compare(VectorOperators.GT, hi);
            VectorMask<Double> far = on.andNot(near);
            VectorMask<Double> onlyFar = far.and(t.compare(VectorOperators.LT, DoubleVector.fromArray(D, lanes.lo, g)));
            VectorMask<Double> cut = far.andNot(onlyFar).and(t.compare(VectorOperators.EQ, t));    // both ways, not in the plane
            toNear |= on.andNot(onlyFar).toLong() << g;
            toFar |= far.toLong() << g;
            curMax.intoArray(farMax, at + g);
            DoubleVector.fromArray(D, lanes.curMin, g).blend(t, cut).intoArray(farMin, at + g);
            if (cut.anyTrue()) {
                curMax.blend(t, cut).intoArray(lanes.curMax, g);
                hi.blend(t.add(t.abs().mul(SLACK)), cut).intoArray(lanes.hi, g);
            }
        }
        lanes.toNear = toNear;
        lanes.toFar = toFar;
    }

    @Override
    public long resume(PacketLanes lanes, long saved, double[] farMin, double[] farMax, int at) {
        long taken = 0;
        for (int g = 0; g < PacketLanes.N; g += L) {
            long bits = saved >>> g & GROUP;
            if (bits == 0) continue;
            DoubleVector start = DoubleVector.fromArray(D, farMin, at + g), stop = DoubleVector.fromArray(D, farMax, at + g);
            DoubleVector best = DoubleVector.fromArray(D, lanes.bestT, g);
            VectorMask<Double> on = VectorMask.fromLong(D, bits).and(start.compare(VectorOperators.LE, best.add(best.abs().mul(SLACK))));
            if (!on.anyTrue()) continue;
            taken |= on.toLong() << g;
            DoubleVector.fromArray(D, lanes.curMin, g).blend(start, on).intoArray(lanes.curMin, g);
            DoubleVector.fromArray(D, lanes.curMax, g).blend(stop, on).intoArray(lanes.curMax, g);
            DoubleVector.fromArray(D, lanes.lo, g).blend(start.sub(start.abs().mul(SLACK)), on).intoArray(lanes.lo, g);
            DoubleVector.fromArray(D, lanes.hi, g).blend(stop.add(stop.abs().mul(SLACK)), on).intoArray(lanes.hi, g);
        }
        return taken;
    }

    @Override
    public void closest(PacketLanes lanes, long active, int[] refs, int start, int end, double[] corners) {
        for (int g = 0; g < PacketLanes.N; g += L) {
            long bits = active >>> g & GROUP;
            if (bits != 0) group(lanes, g, bits, refs, start, end, corners, false);
        }
    }

    @Override
    public long any(PacketLanes lanes, long active, int[] refs, int start, int end, double[] corners) {
        long hit = 0;
        for (int g = 0; g < PacketLanes.N; g += L) {
            long bits = active >>> g & GROUP;
            if (bits != 0) hit |= group(lanes, g, bits, refs, start, end, corners, true) << g;
        }
        return hit;
    }

    /**
     * The lanes {@code bits} of the group from lane {@code g} test the leaf's triangles in order,
     * keeping their closest hits (or, {@code any}, each stopping at its first). The hits so far stay
     * in the lanes' arrays, read per triangle and written where a lane finds a closer one: a vector
     * carried from one iteration to the next would be boxed (allocated) by C2. {@return the group's
     * lanes that hit}
     */
    private static long group(PacketLanes lanes, int g, long bits, int[] refs, int start, int end, double[] c, boolean any) {
        VectorMask<Double> x1 = VectorMask.fromLong(D, lanes.xIs1 >>> g), x2 = VectorMask.fromLong(D, lanes.xIs2 >>> g);
        VectorMask<Double> y1 = VectorMask.fromLong(D, lanes.yIs1 >>> g), y2 = VectorMask.fromLong(D, lanes.yIs2 >>> g);
        VectorMask<Double> z1 = VectorMask.fromLong(D, lanes.zIs1 >>> g), z2 = VectorMask.fromLong(D, lanes.zIs2 >>> g);
        DoubleVector ox = DoubleVector.fromArray(D, lanes.okx, g), oy = DoubleVector.fromArray(D, lanes.oky, g),
                oz = DoubleVector.fromArray(D, lanes.okz, g);
        DoubleVector shx = DoubleVector.fromArray(D, lanes.sx, g), shy = DoubleVector.fromArray(D, lanes.sy, g),
                shz = DoubleVector.fromArray(D, lanes.sz, g);
        DoubleVector tMin = DoubleVector.fromArray(D, lanes.tMin, g), tMax = DoubleVector.fromArray(D, lanes.tMax, g);
        long live = bits, hit = 0;
        for (int r = start; r < end; r++) {
            int pr = refs[r], q = 9 * pr;
            DoubleVector a0 = DoubleVector.broadcast(D, c[q]), a1 = DoubleVector.broadcast(D, c[q + 1]), a2 = DoubleVector.broadcast(D, c[q + 2]);
            DoubleVector b0 = DoubleVector.broadcast(D, c[q + 3]), b1 = DoubleVector.broadcast(D, c[q + 4]), b2 = DoubleVector.broadcast(D, c[q + 5]);
            DoubleVector c0 = DoubleVector.broadcast(D, c[q + 6]), c1 = DoubleVector.broadcast(D, c[q + 7]), c2 = DoubleVector.broadcast(D, c[q + 8]);
            // Each lane's corner coordinates on its shear axes, then the watertight test as in ScalarPacketKernel.
            DoubleVector az = a0.blend(a1, z1).blend(a2, z2).sub(oz), bz = b0.blend(b1, z1).blend(b2, z2).sub(oz),
                    cz = c0.blend(c1, z1).blend(c2, z2).sub(oz);
            DoubleVector ax = a0.blend(a1, x1).blend(a2, x2).sub(ox).sub(shx.mul(az)), ay = a0.blend(a1, y1).blend(a2, y2).sub(oy).sub(shy.mul(az));
            DoubleVector bx = b0.blend(b1, x1).blend(b2, x2).sub(ox).sub(shx.mul(bz)), by = b0.blend(b1, y1).blend(b2, y2).sub(oy).sub(shy.mul(bz));
            DoubleVector cx = c0.blend(c1, x1).blend(c2, x2).sub(ox).sub(shx.mul(cz)), cy = c0.blend(c1, y1).blend(c2, y2).sub(oy).sub(shy.mul(cz));
            DoubleVector u = cx.mul(by).sub(cy.mul(bx)), v = ax.mul(cy).sub(ay.mul(cx)), e = bx.mul(ay).sub(by.mul(ax));
            VectorMask<Double> outside = u.compare(VectorOperators.LT, 0).or(v.compare(VectorOperators.LT, 0)).or(e.compare(VectorOperators.LT, 0))
                    .and(u.compare(VectorOperators.GT, 0).or(v.compare(VectorOperators.GT, 0)).or(e.compare(VectorOperators.GT, 0)));
            DoubleVector det = u.add(v).add(e);
            VectorMask<Double> ok = VectorMask.fromLong(D, live).andNot(outside).and(det.compare(VectorOperators.NE, 0));
            if (!ok.anyTrue()) continue;
            DoubleVector t = u.mul(az).add(v.mul(bz)).add(e.mul(cz)).mul(shz).div(det), best = DoubleVector.fromArray(D, lanes.bestT, g);
            ok = ok.and(t.compare(VectorOperators.GE, tMin)).and(t.compare(VectorOperators.LE, tMax));
            VectorMask<Double> tie = ok.and(t.compare(VectorOperators.EQ, best));
            ok = ok.and(t.compare(VectorOperators.LT, best));
            if (tie.anyTrue()) ok = ok.or(tie.and(DoubleVector.fromArray(D, lanes.bestPrim, g).compare(VectorOperators.GT, pr)));
            if (!ok.anyTrue()) continue;
            DoubleVector.fromArray(D, lanes.bestPrim, g).blend(pr, ok).intoArray(lanes.bestPrim, g);
            best.blend(t, ok).intoArray(lanes.bestT, g);
            DoubleVector.fromArray(D, lanes.bestU, g).blend(v.div(det), ok).intoArray(lanes.bestU, g);
            DoubleVector.fromArray(D, lanes.bestV, g).blend(e.div(det), ok).intoArray(lanes.bestV, g);
            long found = ok.toLong();
            hit |= found;
            if (any && (live &= ~found) == 0) break;
        }
        return hit;
    }
}
