package org.kdtree.tree;

import org.kdtree.geom.Box;

/**
 * A built kd-tree: immutable flat arrays, in the spirit of pbrt's compact nodes.
 *
 * <p>Nodes are stored depth first; the left child of interior node {@code n} is
 * {@code n + 1}. Each node costs 12 bytes: an {@code int} word and a {@code double} split
 * position (double because the geometry is double: a float split would have to move the
 * plane off the primitive bounds the builder chose). The word of an interior node holds
 * {@code rightChild << 5 | axis}; the word of a leaf holds {@code leafIndex << 5 | 31}. The
 * primitives of leaf {@code l} are {@code refs[leafStart[l] .. leafStart[l+1])}, one shared
 * array for all leaves. Hence up to 31 dimensions and 2^26 nodes.
 *
 * <p>The arrays are exposed read-only by convention to the traversal hot path.
 */
public final class KdTree {
    static final int AXIS_BITS = 5;
    /** Axis value that marks a leaf. */
    static final int LEAF_MARK = (1 << AXIS_BITS) - 1;
    static final int MAX_NODE = (1 << (31 - AXIS_BITS)) - 1;

    private final Box bounds;
    private final CostModel cost;
    private final String builderName;
    private final int[] word;
    private final double[] split;
    private final int[] leafStart;
    private final int[] refs;
    private final int budgetLeaves;
    private TreeStats stats;

    KdTree(Box bounds, CostModel cost, String builderName, int[] word, double[] split, int[] leafStart, int[] refs,
           int budgetLeaves) {
        this.budgetLeaves = budgetLeaves;
        this.bounds = bounds;
        this.cost = cost;
        this.builderName = builderName;
        this.word = word;
        this.split = split;
        this.leafStart = leafStart;
        this.refs = refs;
    }

    /** k, the dimension. */
    public int dimension() { return bounds.dimension(); }

    /** The root voxel (a copy). */
    public Box bounds() { return bounds.copy(); }

    /** The Kt and Ki used for {@link TreeStats#expectedCost()}. */
    public CostModel costModel() { return cost; }

    /** The name of the builder that made this tree. */
    public String builderName() { return builderName; }

    public int nodeCount() { return word.length; }

    /**
     * Leaves the build made early because the reference budget ran out
     * ({@code KdTreeBuilder.referenceBudget}); 0 when the tree is the one the builder's own rules make.
     */
    public int budgetLeaves() { return budgetLeaves; }
    public int leafCount() { return leafStart.length - 1; }

    // ---- node access, for traversal (hot path: no allocation) ----

    public boolean isLeaf(int node) { return (word[node] & LEAF_MARK) == LEAF_MARK; }
    public int axis(int node) { return word[node] & LEAF_MARK; }
    public double split(int node) { return split[node]; }
    public int leftChild(int node) { return node + 1; }
    public int rightChild(int node) { return word[node] >>> AXIS_BITS; }
    public int leafIndex(int node) { return word[node] >>> AXIS_BITS; }
    public int leafStart(int node) { return leafStart[leafIndex(node)]; }
    public int leafEnd(int node) { return leafStart[leafIndex(node) + 1]; }
    public int leafSize(int node) { return leafEnd(node) - leafStart(node); }
    /** The i-th entry of the shared leaf reference array. */
    public int ref(int i) { return refs[i]; }

    /** The raw arrays, for flat hot loops (traversal); never modify them. */
    public int[] wordArray() { return word; }
    public double[] splitArray() { return split; }
    public int[] leafStartArray() { return leafStart; }
    public int[] refArray() { return refs; }

    /** The primitives of a leaf node, as a new array. */
    public int[] leafPrimitives(int node) {
        return java.util.Arrays.copyOfRange(refs, leafStart(node), leafEnd(node));
    }

    /** Visits every node depth first, left child first, with its voxel and depth. */
    public void walk(TreeVisitor visitor) {
        walk(0, 0, bounds.copy(), visitor);
    }

    private void walk(int node, int depth, Box voxel, TreeVisitor v) {
        if (isLeaf(node)) {
            v.leaf(node, depth, voxel, refs, leafStart(node), leafEnd(node));
            return;
        }
        int axis = axis(node);
        double xi = split[node];
        v.interior(node, depth, voxel, axis, xi);
        double lo = voxel.min(axis), hi = voxel.max(axis);
        voxel.setMax(axis, xi);
        walk(node + 1, depth + 1, voxel, v);
        voxel.setMax(axis, hi).setMin(axis, xi);
        walk(rightChild(node), depth + 1, voxel, v);
        voxel.setMin(axis, lo);
    }

    /** The tree's statistics (computed once). */
    public TreeStats stats() {
        if (stats == null) stats = TreeStatistics.of(this);
        return stats;
    }

    /** Bytes held by the arrays (12 per node, 4 per leaf, 4 per reference, plus headers). */
    public long memoryBytes() {
        return 16L * 4 + 4L * word.length + 8L * split.length + 4L * leafStart.length + 4L * refs.length;
    }
}
