package org.kdtree.kdtree;

import org.kdtree.accel.Hit;
import org.kdtree.accel.SlabClip;
import org.kdtree.accel.TriangleIntersector;
import org.kdtree.geom.Box;
import org.kdtree.geom.Ray;

/**
 * The specialised 3-D path of {@link Traverser} for triangle meshes: the same algorithm and the
 * same robustness rules as the generic loop, on the flat arrays, with the ray in locals, the
 * per-ray shear of the watertight test computed once, and a leaf's triangles through the leaf
 * kernel ({@link RayKernel}) over the tree's tracing layout (the mesh's corners, {@link
 * KdTree#corners}, from a reference's primitive). Not thread safe: owned by one traverser.
 */
final class MeshTraversal {
    /** A 3-D tree's {@link KdTree#axisBits()}, a constant the JIT folds into the node decoding. */
    private static final int BITS = Nodes.axisBits(3);
    private static final double SLACK = Traverser.SLACK;

    /** The tree's nodes, read with {@link Nodes}. */
    private final int[] nodes;
    private final int[] refs;
    /** The mesh's corners, 9 per triangle ({@link KdTree#corners}). */
    private final double[] corners;
    /** The scene box: 3 minima, then 3 maxima ({@link SlabClip#clip3}'s form). */
    private final double[] scene;
    private final Mailbox mailbox;
    private final int[] stackNode;
    private final double[] stackMin, stackMax;
    private final double[] org = new double[3], inv = new double[3], interval = new double[2];
    private final Hit scratch = new Hit();

    /** The leaf kernel (one for every JVM: {@link RayKernel}). */
    static final RayKernel KERNEL = new ScalarRayKernel();

    MeshTraversal(KdTree tree, Mailbox mailbox, int stackSize) {
        this.mailbox = mailbox;
        if (tree.axisBits() != BITS) throw new IllegalArgumentException("a 3-D tree's axis field is " + BITS + " bits");
        nodes = tree.nodes;
        refs = tree.refs;
        corners = tree.corners;
        if (corners == null) throw new IllegalArgumentException("a tree over a triangle mesh has a tracing layout; this one holds other primitives");
        Box b = tree.bounds();
        scene = new double[] {b.min(0), b.min(1), b.min(2), b.max(0), b.max(1), b.max(2)};
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
        if (ray.dimension() != 3) throw new IllegalArgumentException("a " + ray.dimension() + "-D ray in a 3-D tree");
        double ox = ray.origin(0), oy = ray.origin(1), oz = ray.origin(2);
        double dx = ray.direction(0), dy = ray.direction(1), dz = ray.direction(2);
        double ix = ray.inverseDirection(0), iy = ray.inverseDirection(1), iz = ray.inverseDirection(2);
        if (!(ox - ox == 0 && oy - oy == 0 && oz - oz == 0 && dx - dx == 0 && dy - dy == 0 && dz - dz == 0)
                || (dx == 0 && dy == 0 && dz == 0))
            throw new IllegalArgumentException("ray has a non-finite or zero origin or direction: " + ray);
        if (!SlabClip.clip3(scene, ox, oy, oz, ix, iy, iz, tMin, tMax, interval)) return false;
        double t0 = interval[0], t1 = interval[1];

        // The watertight test's shear, once per ray.
        int kz = TriangleIntersector.maxAxis(dx, dy, dz);
        int kx = kz == 2 ? 0 : kz + 1, ky = kx == 2 ? 0 : kx + 1;
        double[] o = org, iv = inv;
        o[0] = ox; o[1] = oy; o[2] = oz;
        iv[0] = ix; iv[1] = iy; iv[2] = iz;
        double dkz = ray.direction(kz);
        if (dkz < 0) { int s = kx; kx = ky; ky = s; }
        double sz = ray.inverseDirection(kz), sx = ray.direction(kx) * sz, sy = ray.direction(ky) * sz; // = 1 / dkz
        double okx = o[kx], oky = o[ky], okz = o[kz];

        RayKernel kernel = KERNEL;
        int stamp = mailbox.next();
        int[] box = mailbox.stamp;
        int[] nodes = this.nodes;
        int[] refs = this.refs;
        double[] c = corners;
        int sp = 0, node = 0;
        double curMin = t0, curMax = t1;
        // The slack-widened bounds, updated only when the interval changes (not per node).
        double lo = curMin - Math.abs(curMin) * SLACK, hi = curMax + Math.abs(curMax) * SLACK;
        boolean found = false;
        while (true) {
            int w = Nodes.word(nodes, node);
            while (!Nodes.isLeaf(w, BITS)) {
                int axis = Nodes.axis(w, BITS);
                double ia = iv[axis];
                double tSplit = (Nodes.split(nodes, node) - o[axis]) * ia;
                int near = Nodes.leftChild(node), far = Nodes.rightChild(w, BITS);
                if (!(ia > 0)) { far = near; near = Nodes.rightChild(w, BITS); }
                if (tSplit > hi) {
                    node = near;
                } else if (tSplit < lo) {
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
                        hi = tSplit + Math.abs(tSplit) * SLACK;
                    }
                    sp++;
                }
                w = Nodes.word(nodes, node);
            }
            int start = Nodes.leafStart(nodes, node), end = start + Nodes.leafSize(w, BITS);
            if (start < end && kernel.hit(refs, start, end, c, box, stamp, okx, oky, okz, kx, ky, kz, sx, sy, sz, tMin, tMax, hit, any)) {
                if (any) return true;
                found = true;
            }
            while (true) {
                if (sp == 0) return found;
                sp--;
                curMin = stackMin[sp];
                if (curMin <= hit.t + Math.abs(hit.t) * SLACK) break;
            }
            node = stackNode[sp];
            curMax = stackMax[sp];
            lo = curMin - Math.abs(curMin) * SLACK;
            hi = curMax + Math.abs(curMax) * SLACK;
        }
    }
}
