package org.kdtree.bvh;

import org.kdtree.accel.Hit;
import org.kdtree.accel.Intersector;
import org.kdtree.accel.RayQuery;
import org.kdtree.accel.SlabClip;
import org.kdtree.accel.TraversalListener;
import org.kdtree.accel.TraversalStack;
import org.kdtree.geom.Ray;
import org.kdtree.geom.Tolerance;

/**
 * The readable traversal of a {@link Bvh}'s binary tree, in any dimension and over any
 * {@link Intersector}, reporting each step to a listener: at an interior node both children's
 * boxes are tested; the nearer one entered is visited first, the other saved with its entry
 * distance; a saved node that starts beyond the closest hit found so far is dropped. Box tests
 * are widened by the kd-tree traversal's slack ({@link Tolerance#TRAVERSAL_SLACK}), so rounding
 * never skips a box that holds the hit ({@link SlabClip#clip}, the kd-tree's own). Not thread safe: one per thread.
 */
final class BvhTraverser implements RayQuery {
    private static final double SLACK = Tolerance.TRAVERSAL_SLACK;

    private final Bvh bvh;
    private final Intersector prims;
    private final TraversalListener listener;
    private final int k;
    private final double[] box;
    private final int[] prim;
    private final TraversalStack stack;
    private final Hit scratch = new Hit();
    /** The intervals of the last box tests: the root's or a left child's, and a right child's. */
    private final double[] ia = new double[2], ib = new double[2];

    /** A traversal of {@code bvh} over the primitives it was built over, telling {@code listener} each step. */
    BvhTraverser(Bvh bvh, TraversalListener listener) {
        this.bvh = bvh;
        this.prims = bvh.intersector();
        this.listener = listener;
        this.k = bvh.dimension();
        this.box = bvh.boxArray();
        this.prim = bvh.primitiveArray();
        this.stack = new TraversalStack(bvh.maxDepth() + 2);
    }

    @Override public boolean closestHit(Ray ray, double tMin, double tMax, Hit hit) {
        hit.reset();
        boolean found = trace(ray, tMin, tMax, hit, false);
        listener.end(found, hit);
        return found;
    }

    @Override public boolean anyHit(Ray ray, double tMin, double tMax) {
        boolean found = trace(ray, tMin, tMax, scratch.reset(), true);
        listener.end(found, scratch);
        return found;
    }

    private boolean trace(Ray ray, double tMin, double tMax, Hit hit, boolean any) {
        ray.requireTraceable(k, "hierarchy");
        TraversalListener l = listener;
        if (bvh.primitiveCount() == 0 || !SlabClip.clip(ray, box, 0, tMin, tMax, ia)) {
            l.missedScene();
            return false;
        }
        l.begin(ia[0], ia[1]);
        boolean found = false;
        stack.clear();
        int node = 0;
        double curMin = ia[0], curMax = ia[1];
        while (true) {
            while (node >= 0 && !bvh.isLeaf(node)) {
                l.boxNode(node, curMin, curMax);
                int a = bvh.left(node), b = bvh.right(node);
                double limit = Math.min(tMax, hit.t);
                boolean inA = enters(ray, a, tMin, limit, ia), inB = enters(ray, b, tMin, limit, ib);
                if (inA && inB) {   // the nearer first, the other saved
                    inA = ia[0] <= ib[0];
                    double[] far = inA ? ib : ia;
                    stack.push(inA ? b : a, far[0], far[1], l);
                }
                double[] in = inA ? ia : ib;
                node = inA ? a : inB ? b : -1;
                curMin = in[0];
                curMax = in[1];
            }
            if (node >= 0) {
                int count = bvh.leafSize(node), first = bvh.leafStart(node);
                l.leaf(node, curMin, curMax, count);
                for (int r = first; r < first + count; r++) {
                    int p = prim[r];
                    boolean h = prims.intersect(p, ray, tMin, tMax, hit);
                    l.primitive(p, h, h ? hit.t : Double.NaN);
                    if (h && any) return true;
                    found |= h;
                }
            }
            if (!stack.popNext(true, hit.t, SLACK, l)) return found;
            node = stack.node();
            curMin = stack.tMin();
            curMax = stack.tMax();
        }
    }

    /** Whether the ray meets {@code node}'s box within {@code [tMin, tMax]}, the interval met left in {@code interval}; tells the listener. */
    private boolean enters(Ray ray, int node, double tMin, double tMax, double[] interval) {
        boolean in = SlabClip.clip(ray, box, 2 * k * node, tMin, tMax, interval);
        listener.boxTest(node, in, interval[0], interval[1]);
        return in;
    }
}
