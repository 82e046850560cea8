package org.kdtree.traverse;

import org.kdtree.geom.Box;
import org.kdtree.geom.Ray;
import org.kdtree.tree.KdTree;

/**
 * The specialised 3-D path of {@link Traverser} for triangle meshes: the same algorithm and the
 * same robustness rules as the generic loop, on the flat arrays, with the ray in locals, the
 * per-ray shear of the watertight test computed once, and the triangle test inlined. Not thread
 * safe: owned by one traverser.
 */
final class MeshTraversal {
    private static final double SLACK = Traverser.SLACK;

    private final int[] word;
    private final double[] split;
    private final int[] leafStart, refs;
    private final double[] corners;
    private final double lx, ly, lz, hx, hy, hz;
    private final Mailbox mailbox;
    private final int[] stackNode;
    private final double[] stackMin, stackMax;
    private final double[] org = new double[3], inv = new double[3];
    private final Hit scratch = new Hit();

    MeshTraversal(KdTree tree, TriangleIntersector tris, Mailbox mailbox, int stackSize) {
        word = tree.wordArray();
        split = tree.splitArray();
        leafStart = tree.leafStartArray();
        refs = tree.refArray();
        corners = tris.cornerArray();
        Box b = tree.bounds();
        lx = b.min(0); ly = b.min(1); lz = b.min(2);
        hx = b.max(0); hy = b.max(1); hz = b.max(2);
        this.mailbox = mailbox;
        stackNode = new int[stackSize];
        stackMin = new double[stackSize];
        stackMax = new double[stackSize];
    }

    boolean closestHit(Ray ray, double tMin, double tMax, Hit hit) {
        hit.reset();
        return trace(ray, tMin, tMax, hit, false);
    }

    boolean anyHit(Ray ray, double tMin, double tMax) {
        return trace(ray, tMin, tMax, scratch.reset(), true);
    }

    private boolean trace(Ray ray, double tMin, double tMax, Hit hit, boolean any) {
        double ox = ray.origin(0), oy = ray.origin(1), oz = ray.origin(2);
        double dx = ray.direction(0), dy = ray.direction(1), dz = ray.direction(2);
        double ix = ray.inverseDirection(0), iy = ray.inverseDirection(1), iz = ray.inverseDirection(2);
        if (!(ox - ox == 0 && oy - oy == 0 && oz - oz == 0 && dx - dx == 0 && dy - dy == 0 && dz - dz == 0)
                || (dx == 0 && dy == 0 && dz == 0))
            throw new IllegalArgumentException("ray has a non-finite or zero origin or direction: " + ray);
        // Clip to the scene box (NaN from 0 * infinity constrains nothing).
        double t0 = tMin, t1 = tMax, a, b;
        a = (lx - ox) * ix; b = (hx - ox) * ix;
        if (ix < 0) { double s = a; a = b; b = s; }
        if (a > t0) t0 = a;
        if (b < t1) t1 = b;
        a = (ly - oy) * iy; b = (hy - oy) * iy;
        if (iy < 0) { double s = a; a = b; b = s; }
        if (a > t0) t0 = a;
        if (b < t1) t1 = b;
        a = (lz - oz) * iz; b = (hz - oz) * iz;
        if (iz < 0) { double s = a; a = b; b = s; }
        if (a > t0) t0 = a;
        if (b < t1) t1 = b;
        t0 = Math.max(tMin, t0 - Math.abs(t0) * SLACK);
        t1 = Math.min(tMax, t1 + Math.abs(t1) * SLACK);
        if (!(t0 <= t1)) return false;

        // The watertight test's shear, once per ray.
        int kz = TriangleIntersector.maxAxis(dx, dy, dz);
        int kx = kz == 2 ? 0 : kz + 1, ky = kx == 2 ? 0 : kx + 1;
        double[] o = org, iv = inv;
        o[0] = ox; o[1] = oy; o[2] = oz;
        iv[0] = ix; iv[1] = iy; iv[2] = iz;
        double dkz = ray.direction(kz);
        if (dkz < 0) { int s = kx; kx = ky; ky = s; }
        double sz = 1.0 / dkz, sx = ray.direction(kx) * sz, sy = ray.direction(ky) * sz;
        double okx = o[kx], oky = o[ky], okz = o[kz];

        int stamp = mailbox.next();
        int[] box = mailbox.stamp;
        int[] word = this.word, refs = this.refs, leafStart = this.leafStart;
        double[] split = this.split, c = corners;
        int sp = 0, node = 0;
        double curMin = t0, curMax = t1;
        boolean found = false;
        while (true) {
            int w = word[node];
            while ((w & 31) != 31) {
                int axis = w & 31;
                double ia = iv[axis];
                double tSplit = (split[node] - o[axis]) * ia;
                int near = node + 1, far = w >>> 5;
                if (!(ia > 0)) { far = near; near = w >>> 5; }
                if (tSplit > curMax + Math.abs(curMax) * SLACK) {
                    node = near;
                } else if (tSplit < curMin - Math.abs(curMin) * SLACK) {
                    node = far;
                } else {
                    stackNode[sp] = far;
                    stackMax[sp] = curMax;
                    node = near;
                    if (tSplit != tSplit) {          // the ray lies in the split plane
                        stackMin[sp] = curMin;
                    } else {
                        stackMin[sp] = tSplit;
                        curMax = tSplit;
                    }
                    sp++;
                }
                w = word[node];
            }
            int leaf = w >>> 5;
            for (int r = leafStart[leaf], end = leafStart[leaf + 1]; r < end; r++) {
                int p = refs[r];
                if (box[p] == stamp) continue;
                box[p] = stamp;
                if (TriangleIntersector.test(c, 9 * p, p, okx, oky, okz, kx, ky, kz, sx, sy, sz, tMin,
                        Math.min(tMax, hit.t), hit)) {
                    if (any) return true;
                    found = true;
                }
            }
            while (true) {
                if (sp == 0) return found;
                sp--;
                curMin = stackMin[sp];
                if (curMin <= hit.t + Math.abs(hit.t) * SLACK) break;
            }
            node = stackNode[sp];
            curMax = stackMax[sp];
        }
    }
}
