package org.kdtree.kdtree;

import java.util.Arrays;
import org.kdtree.accel.CostModel;
import org.kdtree.geom.Box;
import org.kdtree.shape.Primitives;

/**
 * Writes a kd-tree into flat arrays in depth-first order, as a builder's recursion emits it:
 * an interior node is followed by its whole left subtree, then its right child (whose index
 * is patched in with {@link #setRightChild}). Subtrees written by other writers (a parallel
 * build) are spliced in with {@link #append}.
 */
public final class KdTreeWriter {
    /** The nodes, laid out as {@link Nodes} says. */
    private int[] nodes = new int[64 * Nodes.INTS];
    private int nodeCount;
    private int[] refs = new int[64];
    private int refCount;
    private int budgetLeaves;
    private final int dimension, axisBits, maxNode, maxLeafSize;

    /**
     * A writer for a tree of {@code dimension} dimensions (1 .. {@link KdTree#MAX_DIMENSION}): it fixes the word's layout.
     *
     * @param dimension k, the tree's dimension
     */
    public KdTreeWriter(int dimension) {
        this.dimension = dimension;
        axisBits = Nodes.axisBits(dimension);
        maxNode = Nodes.maxNode(dimension);
        maxLeafSize = Nodes.maxLeafSize(axisBits);
    }

    /**
     * Writes an interior node and returns its index; its left child is the next node written.
     *
     * @param axis the split axis, 0 .. k-1
     * @param xi the split plane's position on {@code axis}
     * @return the new node's index
     */
    public int interior(int axis, double xi) {
        if (axis < 0 || axis >= dimension)
            throw new IllegalArgumentException("axis " + axis + " out of range 0.." + (dimension - 1));
        int n = newNode();
        Nodes.writeInterior(nodes, n, axis, xi); // right child patched later
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
        Nodes.writeRightChild(nodes, node, child, axisBits);
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
        Nodes.writeLeaf(nodes, n, refCount, count, axisBits);
        refCount += count;
        return n;
    }

    /**
     * Appends the whole tree written by {@code sub} as the next subtree; returns its root index.
     *
     * @param sub a finished writer of the same dimension
     * @return the node index of the appended subtree's root
     */
    public int append(KdTreeWriter sub) {
        if (sub.dimension != dimension) throw new IllegalArgumentException("a subtree of another dimension");
        if ((long) nodeCount + sub.nodeCount > maxNode) throw new IllegalStateException("tree exceeds " + maxNode + " nodes");
        int base = nodeCount, refBase = refCount;
        if (refCount + sub.refCount > refs.length) refs = Arrays.copyOf(refs, Math.max(refs.length * 2, refCount + sub.refCount));
        System.arraycopy(sub.refs, 0, refs, refCount, sub.refCount);
        refCount += sub.refCount;
        for (int i = 0; i < sub.nodeCount; i++) {
            int n = newNode(); // first: it may grow the array
            Nodes.copyMoved(sub.nodes, i, nodes, n, base, refBase, axisBits);
        }
        budgetLeaves += sub.budgetLeaves;
        return base;
    }

    /** What a writer has written up to some moment ({@link #mark}), to go back to ({@link #rewind}). */
    record Mark(int nodes, int refs, int budgetLeaves) {
    }

    /** {@return what has been written so far}, for {@link #rewind} to go back to (a trial split's subtree that did not pay) */
    Mark mark() { return new Mark(nodeCount, refCount, budgetLeaves); }

    /**
     * Forgets what was written after {@code m}, keeping the arrays: the next node written takes the
     * place of the first node forgotten.
     * @param m a mark of this writer, taken since its last {@link #clear}
     */
    void rewind(Mark m) {
        nodeCount = m.nodes();
        refCount = m.refs();
        budgetLeaves = m.budgetLeaves();
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
     * @param primitives what it was built over: its ray queries trace them
     * @param rootVoxel the scene box, the root's voxel
     * @param cost the Kt and Ki the tree reports its expected cost with
     * @param builderName the name of the builder, for reports
     * @return the tree
     */
    public KdTree finish(Primitives primitives, Box rootVoxel, CostModel cost, String builderName) {
        if (primitives.dimension() != dimension)
            throw new IllegalArgumentException(primitives.dimension() + "-D primitives for a writer of another dimension");
        if (rootVoxel.dimension() != dimension)
            throw new IllegalArgumentException("a " + rootVoxel.dimension() + "-D root for a writer of another dimension");
        if (nodeCount == 0) leaf(new int[0], 0);
        return new KdTree(primitives, rootVoxel.copy(), cost, builderName, Arrays.copyOf(nodes, Nodes.INTS * nodeCount),
                Arrays.copyOf(refs, refCount), budgetLeaves);
    }

    private int newNode() {
        if (Nodes.INTS * nodeCount == nodes.length) nodes = Arrays.copyOf(nodes, Math.max(2 * Nodes.INTS, nodes.length * 2));
        return nodeCount++;
    }
}
