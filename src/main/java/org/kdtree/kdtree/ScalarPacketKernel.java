package org.kdtree.kdtree;

import org.kdtree.accel.Hit;
import org.kdtree.accel.TriangleIntersector;

/**
 * The packet loop's kernels on Java 17: a lane at a time, each lane's work written as {@link
 * MeshTraversal} does it for a single ray (the same operations in the same order; a leaf's
 * triangles through {@link TriangleIntersector#test}), over the set bits of the lane mask.
 * Stateless: one for every thread.
 */
final class ScalarPacketKernel implements PacketKernel {
    private static final double SLACK = Traverser.SLACK;

    @Override
    public void node(PacketLanes lanes, long active, int axis, double plane, double[] farMin, double[] farMax, int at) {
        double[] o = lanes.origin[axis], iv = lanes.inverse[axis], curMin = lanes.curMin, curMax = lanes.curMax, lo = lanes.lo, hi = lanes.hi;
        long toNear = 0, toFar = 0;
        for (long m = active; m != 0; m &= m - 1) {
            int i = Long.numberOfTrailingZeros(m);
            long bit = 1L << i;
            double t = (plane - o[i]) * iv[i];
            if (t > hi[i]) {
                toNear |= bit;
                continue;
            }
            toFar |= bit;
            farMax[at + i] = curMax[i];
            if (t < lo[i] || t != t) {                  // only far, or NaN: the ray lies in the split plane
                farMin[at + i] = curMin[i];
                if (t < lo[i]) continue;
            } else {
                farMin[at + i] = t;
                curMax[i] = t;
                hi[i] = t + Math.abs(t) * SLACK;
            }
            toNear |= bit;
        }
        lanes.toNear = toNear;
        lanes.toFar = toFar;
    }

    @Override
    public long resume(PacketLanes lanes, long saved, double[] farMin, double[] farMax, int at) {
        long taken = 0;
        for (long m = saved; m != 0; m &= m - 1) {
            int i = Long.numberOfTrailingZeros(m);
            double start = farMin[at + i], best = lanes.bestT[i];
            if (!(start <= best + Math.abs(best) * SLACK)) continue;
            double stop = farMax[at + i];
            lanes.curMin[i] = start;
            lanes.curMax[i] = stop;
            lanes.lo[i] = start - Math.abs(start) * SLACK;
            lanes.hi[i] = stop + Math.abs(stop) * SLACK;
            taken |= 1L << i;
        }
        return taken;
    }

    @Override
    public void closest(PacketLanes lanes, long active, int[] refs, int start, int end, double[] corners) {
        leaf(lanes, active, refs, start, end, corners, false);
    }

    @Override
    public long any(PacketLanes lanes, long active, int[] refs, int start, int end, double[] corners) {
        return leaf(lanes, active, refs, start, end, corners, true);
    }

    /**
     * Each lane of {@code active} tests the leaf's triangles in order with {@link
     * TriangleIntersector#test} (stopping at its first hit if {@code any}), its closest hit so far
     * held in {@link PacketLanes#laneHit}. {@return the lanes that hit}
     */
    private static long leaf(PacketLanes lanes, long active, int[] refs, int start, int end, double[] c, boolean any) {
        long hit = 0;
        Hit h = lanes.laneHit;
        for (long m = active; m != 0; m &= m - 1) {
            int i = Long.numberOfTrailingZeros(m);
            int x = lanes.kx[i], y = lanes.ky[i], z = lanes.kz[i];
            double ox = lanes.okx[i], oy = lanes.oky[i], oz = lanes.okz[i], shx = lanes.sx[i], shy = lanes.sy[i], shz = lanes.sz[i];
            double tMin = lanes.tMin[i], tMax = lanes.tMax[i];
            h.primitive = (int) lanes.bestPrim[i];
            h.t = lanes.bestT[i];
            boolean found = false;
            for (int r = start; r < end; r++) {
                int pr = refs[r];
                if (!TriangleIntersector.test(c, 9 * pr, pr, ox, oy, oz, x, y, z, shx, shy, shz, tMin, tMax, h)) continue;
                found = true;
                if (any) break;
            }
            if (!found) continue;
            lanes.bestPrim[i] = h.primitive;
            lanes.bestT[i] = h.t;
            lanes.bestU[i] = h.u;
            lanes.bestV[i] = h.v;
            hit |= 1L << i;
        }
        return hit;
    }
}
