package org.kdtree.points;

import org.kdtree.kdtree.KdTree;
import org.kdtree.kdtree.KdTreeBuilder;
import org.kdtree.shape.PointsKd;

/**
 * k-D points and a kd-tree built over them, ready for point queries ({@link NearestQuery},
 * {@link RadiusQuery}, {@link BoxQuery}). Immutable, and shared by the query objects of any
 * number of threads.
 *
 * <p>The coordinates are copied once in leaf order (the order of {@link KdTree#refArray()}), so
 * a leaf's points lie next to each other in memory and a leaf scan reads one short run of
 * doubles instead of jumping around the input: k doubles per point, beside the tree.
 */
public final class PointTree {
    /** The most dimensions a tree holds ({@link KdTree#MAX_DIMENSION}). */
    public static final int MAX_DIMENSION = KdTree.MAX_DIMENSION;

    private final PointsKd points;
    private final KdTree tree;
    private final double[] leafCoords;
    private final int maxDepth;

    /**
     * @param points the points
     * @param tree   a tree built over exactly these points, by any builder (each point listed in
     *               one leaf, as every builder of the project lists points)
     */
    public PointTree(PointsKd points, KdTree tree) {
        tree.requireDimension(points.dimension(), "points");
        this.points = points;
        this.tree = tree;
        this.leafCoords = inLeafOrder(points, tree.refArray());
        this.maxDepth = maxDepth(tree);
    }

    /**
     * Builds {@code builder}'s tree over {@code points} (at most {@link #MAX_DIMENSION}-D).
     *
     * @param points  the points, at most {@link #MAX_DIMENSION}-D
     * @param builder the builder that makes the tree
     * @return the points with their new tree
     * @throws IllegalArgumentException if the points have more than {@link #MAX_DIMENSION} dimensions
     */
    public static PointTree build(PointsKd points, KdTreeBuilder builder) {
        if (points.dimension() > MAX_DIMENSION)
            throw new IllegalArgumentException("the points are " + points.dimension() + "-D; a kd-tree here holds at most "
                    + MAX_DIMENSION + " dimensions");
        return new PointTree(points, builder.build(points));
    }

    /** {@return the points, in their input order} */
    public PointsKd points() { return points; }
    /** {@return the tree built over the points} */
    public KdTree tree() { return tree; }
    /** {@return k, the number of coordinates of each point} */
    public int dimension() { return points.dimension(); }
    /** {@return the number of points} */
    public int size() { return points.size(); }

    /** The coordinates in leaf order: those of {@code tree().ref(j)} at {@code [j k, (j + 1) k)}; never modify. */
    double[] leafCoordArray() { return leafCoords; }

    /** The depth of the deepest leaf (the root has depth 0). */
    int maxDepth() { return maxDepth; }

    private static double[] inLeafOrder(PointsKd points, int[] refs) {
        int n = points.size(), k = points.dimension();
        if (refs.length != n)
            throw new IllegalArgumentException("the tree lists " + refs.length + " references for " + n
                    + " points: it was not built over these points");
        boolean[] seen = new boolean[n];
        double[] c = new double[n * k];
        for (int j = 0; j < n; j++) {
            int i = refs[j];
            if (i < 0 || i >= n || seen[i])
                throw new IllegalArgumentException("the tree lists point " + i + " twice or out of range: it was not built over these points");
            seen[i] = true;
            for (int a = 0; a < k; a++) c[j * k + a] = points.coord(i, a);
        }
        return c;
    }

    /** One pass over the depth-first node order, where every parent comes before its children. */
    private static int maxDepth(KdTree tree) {
        int[] depth = new int[tree.nodeCount()];
        int max = 0;
        for (int node = 0; node < depth.length; node++) {
            max = Math.max(max, depth[node]);
            if (tree.isLeaf(node)) continue;
            depth[tree.leftChild(node)] = depth[node] + 1;
            depth[tree.rightChild(node)] = depth[node] + 1;
        }
        return max;
    }
}
