package org.kdtree.check;

import java.util.Arrays;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import org.kdtree.geom.Box;
import org.kdtree.kdtree.KdTree;
import org.kdtree.kdtree.KdTreeBuilder;
import org.kdtree.shape.Primitives;

/**
 * The invariants every kd-tree must satisfy, checked with messages a student can act on. Three
 * of them are the library's self-checks, which no builder can fail: the recursion enforces the
 * tree's shape, the depth cap and a split inside its voxel for every builder (a plane outside its
 * voxel is refused as the builder's fault before it is used); should one fail, the message says
 * it is a bug of kdtree's, not of the builder. The others are the builder's to keep.
 * Coordinates are compared with a margin of {@link org.kdtree.geom.Tolerance#CHECK_MARGIN} of the scene's size, so that rounding in
 * the sample points never raises a false alarm.
 */
final class TreeChecks {
    private TreeChecks() {
    }

    /**
     * Checks every invariant of {@code tree}, built by {@code builder} over {@code prims}.
     * @param builder the builder (for its name and depth cap)
     * @param prims the scene
     * @param tree the tree built over it
     * @throws ContractViolation naming the first invariant that broke
     */
    public static void checkAll(KdTreeBuilder builder, Primitives prims, KdTree tree) {
        TreeInspector in = new TreeInspector(tree);
        double eps = margin(tree.bounds());
        checkShape(builder, tree, in);                 // the library's self-checks
        checkDepth(builder, prims, in);
        checkSplitsInsideVoxels(builder, in);
        checkLeavesTileRoot(builder, tree, in);
        checkEveryReferenceTouchesItsLeaf(builder, prims, in, eps);
        checkEveryPrimitiveIsInEveryLeafItOverlaps(builder, prims, in, eps);
    }

    /** The end of a self-check's message: whose bug it is. */
    static final String SELF_CHECK = " (a self-check of the library: the recursion enforces this for every builder, "
            + "so this is a bug of kdtree's, not of the builder; please report it)";

    static double margin(Box root) {
        double size = 0;
        for (int a = 0; a < root.dimension(); a++)
            size = Math.max(size, Math.max(Math.abs(root.min(a)), Math.abs(root.max(a))));
        return Math.max(org.kdtree.geom.Tolerance.CHECK_MARGIN * size, Double.MIN_NORMAL);
    }

    static void checkShape(KdTreeBuilder b, KdTree tree, TreeInspector in) {
        if (in.leaves().size() != in.interiors().size() + 1)
            fail(b.name() + ": a kd-tree is a full binary tree, so it has one more leaf than interior nodes; this one has "
                    + in.leaves().size() + " leaves and " + in.interiors().size() + " interior nodes" + SELF_CHECK);
        if (tree.nodeCount() != in.leaves().size() + in.interiors().size())
            fail(b.name() + ": " + tree.nodeCount() + " nodes stored but only " + (in.leaves().size() + in.interiors().size())
                    + " reachable from the root" + SELF_CHECK);
    }

    static void checkDepth(KdTreeBuilder b, Primitives prims, TreeInspector in) {
        int cap = b.depthCap(prims.size());
        for (TreeInspector.Leaf l : in.leaves())
            if (l.depth() > cap)
                fail(b.name() + ": leaf at depth " + l.depth() + " but the depth cap Kmaxdepth is " + cap + SELF_CHECK);
    }

    static void checkSplitsInsideVoxels(KdTreeBuilder b, TreeInspector in) {
        for (TreeInspector.Interior n : in.interiors()) {
            Box v = n.voxel();
            if (n.split() < v.min(n.axis()) || n.split() > v.max(n.axis()))
                fail(b.name() + ": node " + n.node() + " at depth " + n.depth() + " splits axis " + n.axis() + " at "
                        + n.split() + ", outside its voxel " + v + SELF_CHECK);
        }
    }

    /** The leaves' voxels cover the root voxel exactly: their measures add up to the root's. */
    static void checkLeavesTileRoot(KdTreeBuilder b, KdTree tree, TreeInspector in) {
        double root = tree.bounds().volume();
        double sum = 0;
        for (TreeInspector.Leaf l : in.leaves()) sum += l.voxel().volume();
        if (Math.abs(sum - root) > org.kdtree.geom.Tolerance.CHECK_MARGIN * Math.max(root, Double.MIN_NORMAL) && root > 0)
            fail(b.name() + ": the leaves' voxels should tile the root voxel (measure " + root
                    + ") but their measures add up to " + sum + ".");
    }

    /** No leaf lists a primitive that does not touch its voxel, nor lists one twice. */
    static void checkEveryReferenceTouchesItsLeaf(KdTreeBuilder b, Primitives prims, TreeInspector in, double eps) {
        Box grown = new Box(prims.dimension()), clip = new Box(prims.dimension());
        for (TreeInspector.Leaf l : in.leaves()) {
            int[] sorted = l.refs().clone();
            Arrays.sort(sorted);
            for (int j = 1; j < sorted.length; j++)
                if (sorted[j] == sorted[j - 1])
                    fail(b.name() + ": leaf " + l.node() + " lists " + prims.describe(sorted[j]) + " twice.");
            grown.set(l.voxel());
            for (int a = 0; a < grown.dimension(); a++) grown.setMin(a, grown.min(a) - eps).setMax(a, grown.max(a) + eps);
            for (int r : l.refs()) {
                if (r < 0 || r >= prims.size()) fail(b.name() + ": leaf " + l.node() + " lists primitive " + r
                        + ", but the scene has primitives 0.." + (prims.size() - 1) + ".");
                prims.clip(r, grown, clip);
                if (clip.isEmpty())
                    fail(b.name() + ": leaf " + l.node() + " (voxel " + l.voxel() + ") lists " + prims.describe(r)
                            + ", which does not touch that voxel; split() must send a primitive only to the child voxels it overlaps.");
            }
        }
    }

    /**
     * Every point of a primitive lies in some leaf that lists it, and every leaf whose voxel holds
     * such a point strictly inside (by a margin) lists the primitive.
     */
    static void checkEveryPrimitiveIsInEveryLeafItOverlaps(KdTreeBuilder b, Primitives prims, TreeInspector in,
                                                          double eps) {
        // each leaf's list sorted once, searched by halves: a leaf of 10,000 identical triangles is asked about each of them
        Map<TreeInspector.Leaf, int[]> sorted = new IdentityHashMap<>();
        for (int i = 0; i < prims.size(); i++) {
            for (double[] p : PrimitiveSamples.of(prims, i)) {
                List<TreeInspector.Leaf> around = in.leavesContaining(p, eps);
                boolean listed = false;
                for (TreeInspector.Leaf l : around) {
                    boolean has = Arrays.binarySearch(sorted.computeIfAbsent(l, TreeChecks::sortedRefs), i) >= 0;
                    listed |= has;
                    if (!has && strictlyInside(p, l.voxel(), eps))
                        fail(b.name() + ": " + prims.describe(i) + " passes through point " + Arrays.toString(p)
                                + ", inside leaf " + l.node() + " (voxel " + l.voxel() + "), but that leaf does not list it;"
                                + " split() must send each primitive to every child voxel it overlaps.");
                }
                if (!listed)
                    fail(b.name() + ": " + prims.describe(i) + " passes through point " + Arrays.toString(p)
                            + ", but no leaf around that point lists it: a ray hitting it there would miss it.");
            }
        }
    }

    /**
     * Strictly inside on every axis. A flat voxel holds no point strictly inside: a split in the
     * plane of a flat scene leaves two leaves with the same voxel, and only one of them need list
     * the primitives lying in it (the first check, "some leaf lists it", still covers them).
     */
    private static boolean strictlyInside(double[] p, Box v, double eps) {
        for (int a = 0; a < v.dimension(); a++) {
            if (!(p[a] > v.min(a) + eps && p[a] < v.max(a) - eps)) return false;
        }
        return true;
    }

    private static void fail(String message) {
        throw new ContractViolation(message);
    }

    private static int[] sortedRefs(TreeInspector.Leaf l) {
        int[] refs = l.refs().clone();
        Arrays.sort(refs);
        return refs;
    }
}
