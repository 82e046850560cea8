package org.kdtree.tree;

import java.util.Arrays;
import org.kdtree.geom.Box;

/**
 * Writes a kd-tree into flat arrays in depth-first order, as a builder's recursion emits it:
 * an interior node is followed by its whole left subtree, then its right child (whose index
 * is patched in with {@link #setRightChild}). Subtrees written by other writers (a parallel
 * build) are spliced in with {@link #append}. Split positions must lie on the tree's
 * {@link SplitGrid} (the build moves its planes there before it partitions).
 */
public final class KdTreeWriter {
    /** Two ints per node, as {@link KdTree} stores them. */
    private int[] nodes = new int[128];
    private int nodeCount;
    private int[] refs = new int[64];
    private int refCount;
    private int budgetLeaves;
    private final Box root;
    private final SplitGrid grid;
    private final int dimension, axisBits, leafMark, maxNode, maxLeafSize;

    /**
     * A writer for a tree whose root voxel is {@code root}: it fixes the word's layout and the grid of split positions.
     *
     * @param root the scene box, the root's voxel (1 .. {@link KdTree#MAX_DIMENSION} dimensions)
     */
    public KdTreeWriter(Box root) {
        this(root.copy(), new SplitGrid(root));
    }

    private KdTreeWriter(Box root, SplitGrid grid) {
        this.root = root;
        this.grid = grid;
        this.dimension = root.dimension();
        axisBits = KdTree.axisBits(dimension);
        leafMark = (1 << axisBits) - 1;
        maxNode = KdTree.maxNode(dimension);
        maxLeafSize = -1 >>> axisBits;
    }

    /** {@return a writer for a subtree of the same tree (same root voxel and grid), for another thread} */
    public KdTreeWriter forSubtree() {
        return new KdTreeWriter(root, grid);
    }

    /** {@return the grid split positions must lie on} */
    public SplitGrid grid() { return grid; }

    /**
     * Writes an interior node and returns its index; its left child is the next node written.
     *
     * @param axis the split axis, 0 .. k-1
     * @param xi the split plane's position on {@code axis}, a position of {@link #grid()}
     * @return the new node's index
     * @throws IllegalArgumentException if the axis is out of range or {@code xi} is not on the grid
     */
    public int interior(int axis, double xi) {
        if (axis < 0 || axis >= dimension)
            throw new IllegalArgumentException("axis " + axis + " out of range 0.." + (dimension - 1));
        float code = grid.code(axis, xi);
        int n = newNode();
        nodes[2 * n] = Float.floatToRawIntBits(code);
        nodes[2 * n + 1] = axis; // right child patched later
        return n;
    }

    /**
     * Sets the right child of interior node {@code node} to the next node to be written.
     *
     * @param node an interior node written earlier
     */
    public void setRightChild(int node) {
        int child = nodeCount;
        if (child > maxNode) throw new IllegalStateException("tree exceeds " + maxNode + " nodes");
        nodes[2 * node + 1] = (child << axisBits) | (nodes[2 * node + 1] & leafMark);
    }

    /**
     * Writes a leaf holding {@code prims[0 .. count)} and returns its node index.
     *
     * @param prims primitive indices
     * @param count how many of them the leaf holds
     * @return the leaf's node index
     */
    public int leaf(int[] prims, int count) {
        return leaf(prims, 0, count);
    }

    /** Notes that the next leaf is written because the reference budget ran out (reported by {@link KdTree#budgetLeaves()}). */
    public void budgetLeaf() {
        budgetLeaves++;
    }

    /**
     * Writes a leaf holding {@code prims[from .. from + count)} and returns its node index.
     *
     * @param prims primitive indices
     * @param from the first of them the leaf holds
     * @param count how many it holds
     * @return the leaf's node index
     */
    public int leaf(int[] prims, int from, int count) {
        if (count > maxLeafSize) throw new IllegalStateException("a leaf of " + count + " references exceeds " + maxLeafSize);
        if (refCount + count > refs.length) refs = Arrays.copyOf(refs, Math.max(refs.length * 2, refCount + count));
        int n = newNode();
        System.arraycopy(prims, from, refs, refCount, count);
        nodes[2 * n] = refCount;
        nodes[2 * n + 1] = (count << axisBits) | leafMark;
        refCount += count;
        return n;
    }

    /**
     * Appends the whole tree written by {@code sub} as the next subtree; returns its root index.
     *
     * @param sub a finished writer of the same tree ({@link #forSubtree})
     * @return the node index of the appended subtree's root
     */
    public int append(KdTreeWriter sub) {
        if (!sub.grid.equals(grid)) throw new IllegalArgumentException("a subtree of another tree");
        if ((long) nodeCount + sub.nodeCount > maxNode) throw new IllegalStateException("tree exceeds " + maxNode + " nodes");
        int base = nodeCount, refBase = refCount;
        if (refCount + sub.refCount > refs.length) refs = Arrays.copyOf(refs, Math.max(refs.length * 2, refCount + sub.refCount));
        System.arraycopy(sub.refs, 0, refs, refCount, sub.refCount);
        refCount += sub.refCount;
        for (int i = 0; i < sub.nodeCount; i++) {
            int n = newNode();
            int first = sub.nodes[2 * i], w = sub.nodes[2 * i + 1];
            boolean leaf = (w & leafMark) == leafMark;
            nodes[2 * n] = leaf ? first + refBase : first;
            nodes[2 * n + 1] = leaf ? w : (((w >>> axisBits) + base) << axisBits) | (w & leafMark);
        }
        budgetLeaves += sub.budgetLeaves;
        return base;
    }

    /**
     * Makes room for {@code nodes} nodes and {@code refs} leaf references, so that a builder that
     * can estimate its tree's size spares the copies of growing by doubling. Writing beyond it still works.
     * @param nodes the expected number of nodes
     * @param refs the expected number of leaf references
     */
    public void reserve(int nodes, int refs) {
        if (this.nodes.length < 2L * nodes) this.nodes = Arrays.copyOf(this.nodes, 2 * nodes);
        if (this.refs.length < refs) this.refs = Arrays.copyOf(this.refs, refs);
    }

    /** Forgets everything written, keeping the arrays, so that the writer can take another (sub)tree. */
    public void clear() {
        nodeCount = 0;
        refCount = 0;
        budgetLeaves = 0;
    }

    /** {@return the number of nodes written so far} */
    public int nodeCount() { return nodeCount; }

    /**
     * Finishes the tree.
     *
     * @param cost the Kt and Ki the tree reports its expected cost with
     * @param builderName the name of the builder, for reports
     * @return the tree
     */
    public KdTree finish(CostModel cost, String builderName) {
        if (nodeCount == 0) leaf(new int[0], 0);
        return new KdTree(root.copy(), grid, cost, builderName,
                Arrays.copyOf(nodes, 2 * nodeCount), Arrays.copyOf(refs, refCount), budgetLeaves);
    }

    private int newNode() {
        if (2 * nodeCount == nodes.length) nodes = Arrays.copyOf(nodes, Math.max(4, nodes.length * 2));
        return nodeCount++;
    }
}
