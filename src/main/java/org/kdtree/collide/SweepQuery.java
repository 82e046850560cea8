package org.kdtree.collide;

import org.kdtree.kdtree.KdTree;

/**
 * The first contact of a moving sphere (a circle in 2-D): its centre moves along
 * {@code s + t d}, t in [0, 1], and the answer is the smallest t at which it touches a primitive,
 * which one, where, and the contact normal ({@link Contact}).
 *
 * <p>The traversal is the ray traversal of {@code kdtree.Traverser} (the talk's Algorithm 2)
 * run on voxels inflated by r. At a split plane {@code x_axis = xi} the near child's inflated
 * voxel ends where the centre passes {@code xi + r} (moving up; {@code xi - r} moving down), the
 * far child's begins where it passes {@code xi - r} (resp. {@code xi + r}): two overlapping
 * intervals, the near one taken first and the far one saved on the stack. Every primitive is
 * tested once, against the whole motion up to the best contact so far; a saved far child is
 * skipped when it starts after that contact. A centre that does not move along the axis visits
 * each child whose inflated slab contains it, over the whole interval.
 *
 * <p>Ties: of several primitives touched at the same t, the one with the smallest index wins, as
 * in {@link BruteForceCollisions}, so both answer the same primitive.
 *
 * <p>An instance holds the stack and mailbox and allocates nothing per query: use one per thread.
 */
public final class SweepQuery extends SphereQuery {
    private final int[] stackNode;
    private final double[] stackMin, stackMax;
    private int tests;
    /** The motion's range clipped to the inflated scene box, from {@link #clipToScene}. */
    private double enter, exit;

    /**
     * @param tree  a tree over the primitives of {@code prims}
     * @param prims the primitives' exact tests, of the tree's dimension
     */
    public SweepQuery(KdTree tree, Collider prims) {
        super(tree, prims);
        int depth = tree.stats().maxDepth() + 2;
        stackNode = new int[depth];
        stackMin = new double[depth];
        stackMax = new double[depth];
    }

    /**
     * Finds the first contact of a sphere of radius {@code r} moving from {@code s} to
     * {@code s + d}; fills {@code contact} and returns true, or resets it and returns false.
     * A sphere touching something at the start answers t = 0; a zero {@code d} asks whether the
     * sphere at {@code s} touches anything.
     *
     * @param s       the centre at the start (t = 0)
     * @param d       the motion: the centre is at {@code s + d} at t = 1
     * @param r       the radius, finite and at least 0
     * @param contact filled with the first contact, or reset when there is none
     * @return whether the sphere touches a primitive on the way
     */
    public boolean firstContact(double[] s, double[] d, double r, Contact contact) {
        SphereQueries.checkPoint("start", s, k);
        SphereQueries.checkPoint("motion", d, k);
        SphereQueries.checkRadius(r);
        contact.reset();
        tests = 0;
        double inflate = r + SphereQueries.pad(sceneScale, s, d, r, k);
        if (!clipToScene(s, d, inflate)) return false;
        tested.next();
        int best = -1, sp = 0, node = 0;
        double bestT = 1, curMin = enter, curMax = exit;
        while (true) {
            while (!tree.isLeaf(node)) {
                int axis = tree.axis(node), left = tree.leftChild(node), right = tree.rightChild(node);
                double xi = tree.split(node), sa = s[axis], da = d[axis];
                if (da == 0) { // not moving across this plane: each child whose slab holds the centre
                    boolean inLeft = sa <= xi + inflate, inRight = sa >= xi - inflate;
                    if (inLeft && inRight) push(sp++, right, curMin, curMax);
                    node = inLeft ? left : right;
                    continue;
                }
                int near = da > 0 ? left : right, far = da > 0 ? right : left;
                double nearEnd = (xi + (da > 0 ? inflate : -inflate) - sa) / da;
                double farStart = (xi - (da > 0 ? inflate : -inflate) - sa) / da;
                boolean goNear = nearEnd >= curMin, goFar = farStart <= curMax;
                if (goNear && goFar) push(sp++, far, Math.max(curMin, farStart), curMax);
                if (goNear) {
                    node = near;
                    curMax = Math.min(curMax, nearEnd);
                } else {
                    node = far;
                    curMin = Math.max(curMin, farStart);
                }
            }
            for (int i = tree.leafStart(node), end = tree.leafEnd(node); i < end; i++) {
                int p = tree.ref(i);
                if (!tested.first(p)) continue;
                tests++;
                double t = prims.firstContact(p, s, d, r, bestT);
                if (t <= bestT && (best < 0 || t < bestT || p < best)) { bestT = t; best = p; }
            }
            // The next saved far child that can still hold an earlier (or equal) contact.
            do {
                if (sp == 0) {
                    if (best >= 0) contact.complete(prims, best, bestT, s, d);
                    return best >= 0;
                }
                sp--;
                node = stackNode[sp];
                curMin = stackMin[sp];
                curMax = stackMax[sp];
            } while (best >= 0 && curMin > bestT);
        }
    }

    /** Clips [0, 1] to the scene box inflated by {@code inflate} into enter and exit; false when empty. */
    private boolean clipToScene(double[] s, double[] d, double inflate) {
        double t0 = 0, t1 = 1;
        for (int a = 0; a < k; a++) {
            double min = lo[a] - inflate, max = hi[a] + inflate;
            if (!(min <= max)) return false; // an empty scene
            if (d[a] == 0) {
                if (s[a] < min || s[a] > max) return false;
                continue;
            }
            double tA = (min - s[a]) / d[a], tB = (max - s[a]) / d[a];
            t0 = Math.max(t0, Math.min(tA, tB));
            t1 = Math.min(t1, Math.max(tA, tB));
        }
        enter = t0;
        exit = t1;
        return t0 <= t1;
    }

    private void push(int sp, int node, double tMin, double tMax) {
        stackNode[sp] = node;
        stackMin[sp] = tMin;
        stackMax[sp] = tMax;
    }

    /** {@return the primitive tests the last query did} Brute force does {@code size()}. */
    public int lastTests() { return tests; }

    /** {@return the tree the queries traverse} */
    public KdTree tree() { return tree; }

    /** {@return the primitives' exact tests} */
    public Collider collider() { return prims; }
}
