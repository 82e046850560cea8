package org.kdtree.kdtree;

import org.kdtree.accel.Hit;
import org.kdtree.accel.TriangleIntersector;

/** The single-ray loop's leaf kernel on Java 17: a leaf's triangles one after the other. Stateless. */
final class ScalarRayKernel implements RayKernel {
    @Override public boolean hit(int[] refs, int start, int end, double[] c, int[] box, int stamp, double okx, double oky, double okz, int kx,
                                 int ky, int kz, double sx, double sy, double sz, double tMin, double tMax, Hit hit, boolean any) {
        boolean found = false;
        for (int r = start; r < end; r++) {
            int p = refs[r];
            if (box[p] == stamp) continue;
            box[p] = stamp;
            if (!TriangleIntersector.test(c, 9 * p, p, okx, oky, okz, kx, ky, kz, sx, sy, sz, tMin, tMax, hit)) continue;
            if (any) return true;
            found = true;
        }
        return found;
    }
}
