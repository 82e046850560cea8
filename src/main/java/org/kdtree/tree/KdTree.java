package org.kdtree.tree;

import org.kdtree.geom.Box;

/**
 * A built kd-tree: immutable flat arrays, in the spirit of pbrt's compact nodes.
 *
 * <p>Nodes are stored depth first; the near-side (lower) child of interior node {@code n} is
 * {@code n + 1}. Each node costs 12 bytes, three {@code int}s of one array, so that a node is one
 * load away (there is no second copy for the traversal): {@code nodes[3n]}, the node's word, holds
 * in its low {@link #axisBits()} bits the split axis, or all ones ({@link #leafMark()}) for a leaf,
 * and in the bits above the upper child's index, or the leaf's number of references;
 * {@code nodes[3n + 1]} and {@code nodes[3n + 2]} hold the low and high halves of an interior
 * node's {@code double} split position (exactly the plane the build partitioned with: a float
 * would move it off the primitive bounds the builder chose, see docs/traversal.md), or a leaf's
 * first index into the shared reference array and 0. The axis field is as narrow as the dimension
 * allows (2 bits in 2-D and 3-D, 7 bits in 64-D), so a 3-D tree may hold 2^29 nodes and a 64-D one
 * 2^24. The primitives of leaf {@code n} are
 * {@code refs[nodes[3n+1] .. nodes[3n+1] + (nodes[3n] >>> axisBits()))}.
 *
 * <p>The arrays are exposed read-only by convention to the hot paths (traversal, point
 * queries), which read them as described here ({@link #splitOf} decodes a split); everything
 * else uses the methods.
 */
public final class KdTree {
    /** The most dimensions a tree may have ({@link org.kdtree.limits.Limits#DIMENSION}). */
    public static final int MAX_DIMENSION = (int) org.kdtree.limits.Limits.DIMENSION.max();

    private final Box bounds;
    private final CostModel cost;
    private final String builderName;
    private final int[] nodes;
    private final int[] refs;
    private final int budgetLeaves;
    private final int axisBits, leafMark;
    private TreeStats stats;

    KdTree(Box bounds, CostModel cost, String builderName, int[] nodes, int[] refs, int budgetLeaves) {
        this.budgetLeaves = budgetLeaves;
        this.bounds = bounds;
        this.cost = cost;
        this.builderName = builderName;
        this.nodes = nodes;
        this.refs = refs;
        this.axisBits = axisBits(bounds.dimension());
        this.leafMark = (1 << axisBits) - 1;
    }

    /**
     * The split position of interior node {@code node} of a node array laid out as this class
     * says: the one decoding, for hot loops that hold the array.
     *
     * @param nodes a tree's {@link #nodeArray()}
     * @param node an interior node's index
     * @return its split position
     */
    public static double splitOf(int[] nodes, int node) {
        return Double.longBitsToDouble((long) nodes[3 * node + 2] << 32 | (nodes[3 * node + 1] & 0xffffffffL));
    }

    /**
     * The width of a word's axis field in a {@code dimension}-D tree: wide enough for every axis and the leaf mark.
     *
     * @param dimension k, 1 .. {@link #MAX_DIMENSION}
     * @return the number of low bits of a word that hold the axis or the leaf mark
     * @throws IllegalArgumentException if {@code dimension} is out of range
     */
    public static int axisBits(int dimension) {
        if (dimension < 1 || dimension > MAX_DIMENSION)
            throw new IllegalArgumentException("a tree has 1 to " + MAX_DIMENSION + " dimensions, not " + dimension);
        return 32 - Integer.numberOfLeadingZeros(dimension);
    }

    /**
     * The largest node index a {@code dimension}-D tree can hold.
     *
     * @param dimension k, 1 .. {@link #MAX_DIMENSION}
     * @return the largest index a node (or leaf) of such a tree may have
     */
    public static int maxNode(int dimension) {
        return (1 << (31 - axisBits(dimension))) - 1;
    }

    /** {@return the width of the axis field at the bottom of a node's word} */
    public int axisBits() { return axisBits; }

    /**
     * {@return the axis field's value in a leaf's word (all ones)}: {@code (w & leafMark()) == leafMark()} tests for a leaf.
     */
    public int leafMark() { return leafMark; }

    /** {@return k, the dimension} */
    public int dimension() { return bounds.dimension(); }

    /**
     * Checks that a query's objects have this tree's dimension.
     *
     * @param dimension their dimension
     * @param what what they are, for the message ("primitives", "points")
     * @throws IllegalArgumentException naming both dimensions if they differ
     */
    public void requireDimension(int dimension, String what) {
        if (dimension != dimension())
            throw new IllegalArgumentException("tree is " + dimension() + "-D, " + what + " " + dimension + "-D");
    }

    /** {@return the root voxel (a copy)} */
    public Box bounds() { return bounds.copy(); }

    /** {@return the Kt and Ki used for {@link TreeStats#expectedCost()}} */
    public CostModel costModel() { return cost; }

    /** {@return the name of the builder that made this tree} */
    public String builderName() { return builderName; }

    /** {@return the number of nodes, interior and leaf} */
    public int nodeCount() { return nodes.length / 3; }

    /**
     * Leaves the build made early because the reference budget ran out
     * ({@code KdTreeBuilder.referenceBudget}); 0 when the tree is the one the builder's own rules make.
     * @return the number of such early leaves
     */
    public int budgetLeaves() { return budgetLeaves; }

    // ---- node access (small enough to be inlined into hot loops) ----

    /**
     * {@return whether {@code node} is a leaf}
     * @param node a node index
     */
    public boolean isLeaf(int node) { return (nodes[3 * node] & leafMark) == leafMark; }
    /**
     * {@return the split axis of interior node {@code node}}
     * @param node an interior node's index
     */
    public int axis(int node) { return nodes[3 * node] & leafMark; }
    /**
     * {@return the split plane's position on the axis of interior node {@code node}}
     * @param node an interior node's index
     */
    public double split(int node) { return splitOf(nodes, node); }
    /**
     * {@return the left (lower) child of interior node {@code node}: always {@code node + 1}}
     * @param node an interior node's index
     */
    public int leftChild(int node) { return node + 1; }
    /**
     * {@return the upper child of interior node {@code node}}
     * @param node an interior node's index
     */
    public int rightChild(int node) { return nodes[3 * node] >>> axisBits; }
    /**
     * {@return where the references of leaf {@code node} begin in {@link #refArray()}}
     * @param node a leaf node's index
     */
    public int leafStart(int node) { return nodes[3 * node + 1]; }
    /**
     * {@return where the references of leaf {@code node} end (exclusive) in {@link #refArray()}}
     * @param node a leaf node's index
     */
    public int leafEnd(int node) { return leafStart(node) + leafSize(node); }
    /**
     * {@return the number of primitive references in leaf {@code node}}
     * @param node a leaf node's index
     */
    public int leafSize(int node) { return nodes[3 * node] >>> axisBits; }
    /**
     * {@return the i-th entry of the shared leaf reference array}
     * @param i an index into {@link #refArray()}
     */
    public int ref(int i) { return refs[i]; }

    /**
     * {@return the nodes, three ints each (see the class comment)}: the raw array for flat hot loops; never modify it.
     */
    public int[] nodeArray() { return nodes; }
    /** {@return the shared leaf reference array (primitive indices), in leaf order}: the raw array; never modify it. */
    public int[] refArray() { return refs; }

    /**
     * {@return the primitives referenced by a leaf node, as a new array}
     * @param node a leaf node's index
     */
    public int[] leafPrimitives(int node) {
        return java.util.Arrays.copyOfRange(refs, leafStart(node), leafEnd(node));
    }

    /**
     * Visits every node depth first, left child first, with its voxel and depth.
     *
     * @param visitor receives every interior node and leaf
     */
    public void walk(TreeVisitor visitor) {
        walk(0, 0, bounds.copy(), visitor);
    }

    private void walk(int node, int depth, Box voxel, TreeVisitor v) {
        if (isLeaf(node)) {
            v.leaf(node, depth, voxel, refs, leafStart(node), leafEnd(node));
            return;
        }
        int axis = axis(node);
        double xi = split(node);
        v.interior(node, depth, voxel, axis, xi);
        double lo = voxel.min(axis), hi = voxel.max(axis);
        voxel.setMax(axis, xi);
        walk(node + 1, depth + 1, voxel, v);
        voxel.setMax(axis, hi).setMin(axis, xi);
        walk(rightChild(node), depth + 1, voxel, v);
        voxel.setMin(axis, lo);
    }

    /** {@return the tree's statistics (computed once)} */
    public TreeStats stats() {
        if (stats == null) stats = TreeStatistics.of(this);
        return stats;
    }

    /** {@return bytes held by the arrays (12 per node, 4 per reference, plus the arrays' headers)} */
    public long memoryBytes() {
        return 2 * 16L + 4L * nodes.length + 4L * refs.length;
    }
}
