package org.kdtree.collide;

import org.kdtree.kdtree.KdTree;
import org.kdtree.kdtree.Mailbox;

/**
 * All primitives overlapping a sphere (a circle in 2-D): those at distance {@code <= r} from its centre,
 * touching included.
 *
 * <p>The traversal descends into every child whose voxel, inflated by r, contains the centre: at
 * a split plane {@code x_axis = xi} the left child when {@code c_axis - r <= xi}, the right one
 * when {@code c_axis + r >= xi}, both when the sphere straddles the plane (the right one saved
 * on a stack). Each primitive of the leaves reached is tested once ({@link Mailbox}) with the
 * exact {@link Collider#closestPoint}. The inflated voxel contains the sphere's Minkowski sum with
 * the voxel, so nothing that touches the sphere is pruned.
 *
 * <p>An instance holds the stack and mailbox and allocates nothing per query: use one per thread
 * (the tree and the collider are shared).
 */
public final class OverlapQuery extends SphereQuery {
    private final int[] stack;
    private int tests;

    /**
     * @param tree  a tree over the primitives of {@code prims}
     * @param prims the primitives' exact tests, of the tree's dimension
     */
    public OverlapQuery(KdTree tree, Collider prims) {
        super(tree, prims);
        stack = new int[tree.stats().maxDepth() + 2];
    }

    /**
     * Writes the primitives within distance {@code r} of {@code centre} into {@code out} (in no
     * particular order, each once) and returns how many there are. When there are more than
     * {@code out.length}, only the first {@code out.length} are written, and the full count is
     * still returned.
     *
     * @param centre the sphere's centre
     * @param r      its radius, finite and at least 0
     * @param out    receives the primitives' indices
     * @return how many primitives overlap the sphere
     */
    public int overlapping(double[] centre, double r, int[] out) {
        SphereQueries.checkPoint("centre", centre, k);
        SphereQueries.checkRadius(r);
        tests = 0;
        double inflate = r + SphereQueries.pad(sceneScale, centre, null, r, k);
        for (int a = 0; a < k; a++)
            if (!(centre[a] + inflate >= lo[a] && centre[a] - inflate <= hi[a])) return 0; // also an empty scene
        tested.next();
        double rr = r * r;
        int count = 0, sp = 0, node = 0;
        while (true) {
            while (!tree.isLeaf(node)) {
                double c = centre[tree.axis(node)], xi = tree.split(node);
                boolean left = c - inflate <= xi, right = c + inflate >= xi;
                if (left && right) stack[sp++] = tree.rightChild(node);
                node = left ? tree.leftChild(node) : tree.rightChild(node);
            }
            for (int i = tree.leafStart(node), end = tree.leafEnd(node); i < end; i++) {
                int p = tree.ref(i);
                if (!tested.first(p)) continue;
                tests++;
                if (prims.closestPoint(p, centre, null) <= rr) {
                    if (count < out.length) out[count] = p;
                    count++;
                }
            }
            if (sp == 0) return count;
            node = stack[--sp];
        }
    }

    /** {@return the primitive tests the last query did} Brute force does {@code size()}. */
    public int lastTests() { return tests; }

    /** {@return the tree the queries descend} */
    public KdTree tree() { return tree; }

    /** {@return the primitives' exact tests} */
    public Collider collider() { return prims; }
}
