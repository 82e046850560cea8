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
    /** The interval of the last {@link #enters} test. */
    private double enter, exit;
    private final double[] interval = new double[2];

    /** A traversal of {@code bvh} over the primitives it was built over, telling {@code listener} each step. */
    BvhTraverser(Bvh bvh, TraversalListener listener) {
        this.bvh = bvh;
        this.prims = bvh.intersector();
        this.listener = listener;
        this.k = bvh.dimension();
        this.box = bvh.boxArray();
        this.prim = bvh.primitiveArray();
        int depth = bvh.maxDepth() + 2;
        stack = new TraversalStack(depth);
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
        if (bvh.primitiveCount() == 0 || !enters(ray, 0, tMin, tMax)) {
            l.missedScene();
            return false;
        }
        l.begin(enter, exit);
        boolean found = false;
        stack.clear();
        int node = 0;
        double curMin = enter, curMax = exit;
        while (true) {
            while (!bvh.isLeaf(node)) {
                l.boxNode(node, curMin, curMax);
                int a = bvh.left(node), b = bvh.right(node);
                double limit = Math.min(tMax, hit.t);
                boolean inA = enters(ray, a, tMin, limit);
                double aMin = enter, aMax = exit;
                l.boxTest(a, inA, aMin, aMax);
                boolean inB = enters(ray, b, tMin, limit);
                double bMin = enter, bMax = exit;
                l.boxTest(b, inB, bMin, bMax);
                if (inA && inB) {
                    boolean aFirst = aMin <= bMin;
                    int far = aFirst ? b : a;
                    double farMin = aFirst ? bMin : aMin, farMax = aFirst ? bMax : aMax;
                    stack.push(far, farMin, farMax, l);
                    node = aFirst ? a : b;
                    curMin = aFirst ? aMin : bMin;
                    curMax = aFirst ? aMax : bMax;
                } else if (inA || inB) {
                    node = inA ? a : b;
                    curMin = inA ? aMin : bMin;
                    curMax = inA ? aMax : bMax;
                } else {
                    node = -1;
                    break;
                }
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

    /** Whether the ray meets {@code node}'s box within {@code [tMin, tMax]}, the interval met left in {@link #enter} and {@link #exit}. */
    private boolean enters(Ray ray, int node, double tMin, double tMax) {
        boolean in = SlabClip.clip(ray, box, 2 * k * node, tMin, tMax, interval);
        enter = interval[0];
        exit = interval[1];
        return in;
    }
}
