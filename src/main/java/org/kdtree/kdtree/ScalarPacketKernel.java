package org.kdtree.kdtree;

/**
 * The packet loop's kernels on Java 17: a lane at a time, each lane's work written as {@link
 * MeshTraversal} does it for a single ray (the same operations in the same order), over the set
 * bits of the lane mask. Stateless: one for every thread.
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
     * Each lane of {@code active} tests the leaf's triangles in order (stopping at its first hit if
     * {@code any}), in one method: the JIT inlines none of the test (above its size limit), so that
     * a leaf costs one call, not one a lane. {@return the lanes that hit}
     */
    private static long leaf(PacketLanes lanes, long active, int[] refs, int start, int end, double[] c, boolean any) {
        long hit = 0;
        for (long m = active; m != 0; m &= m - 1) {
            int i = Long.numberOfTrailingZeros(m);
            int x = lanes.kx[i], y = lanes.ky[i], z = lanes.kz[i];
            double prim = lanes.bestPrim[i];
            double ox = lanes.okx[i], oy = lanes.oky[i], oz = lanes.okz[i], shx = lanes.sx[i], shy = lanes.sy[i], shz = lanes.sz[i];
            double tMin = lanes.tMin[i], tMax = lanes.tMax[i], best = lanes.bestT[i], bu = lanes.bestU[i], bv = lanes.bestV[i];
            boolean found = false;
            for (int r = start; r < end; r++) {
                // TriangleIntersector.test, written out as in MeshTraversal (the JIT will not inline it).
                int pr = refs[r], q = 9 * pr;
                double az = c[q + z] - oz, bz = c[q + 3 + z] - oz, cz = c[q + 6 + z] - oz;
                double ax = c[q + x] - ox - shx * az, ay = c[q + y] - oy - shy * az;
                double bx = c[q + 3 + x] - ox - shx * bz, by = c[q + 3 + y] - oy - shy * bz;
                double cx = c[q + 6 + x] - ox - shx * cz, cy = c[q + 6 + y] - oy - shy * cz;
                double u = cx * by - cy * bx, v = ax * cy - ay * cx, e = bx * ay - by * ax;
                if ((u < 0 || v < 0 || e < 0) && (u > 0 || v > 0 || e > 0)) continue;
                double det = u + v + e;
                if (det == 0) continue;
                double t = (u * az + v * bz + e * cz) * shz / det;
                if (!(t >= tMin && t <= tMax && (t < best || t == best && pr < prim))) continue;
                found = true;
                prim = pr;
                best = t;
                bu = v / det;
                bv = e / det;
                if (any) break;
            }
            if (!found) continue;
            lanes.bestPrim[i] = prim;
            lanes.bestT[i] = best;
            lanes.bestU[i] = bu;
            lanes.bestV[i] = bv;
            hit |= 1L << i;
        }
        return hit;
    }
}
