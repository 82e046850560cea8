package org.kdtree.kdtree;

/**
 * The node layout of a {@link KdTree}, and the only code that knows it: how a node's three ints
 * say leaf or interior node, split axis, split plane, children and a leaf's primitives. Every
 * reader of a tree's {@link KdTree#nodeArray()} decodes it with these small static methods, which
 * the JIT inlines into the hot loops (ray traversal, point queries), so that the loops stay flat
 * primitive-array code and the layout can change in this one file.
 *
 * <p>A node is three ints, depth first. The first is the node's <em>word</em>: its low
 * {@code axisBits} bits (as few as the dimension allows, {@link #axisBits(int)}) hold the split
 * axis, or all ones for a leaf; the bits above hold an interior node's right (upper) child, or a
 * leaf's number of primitive references. The other two hold the low and high halves of an
 * interior node's {@code double} split position (exactly the plane the build partitioned with),
 * or a leaf's first index into the tree's shared reference array and 0. The left (lower) child of
 * interior node {@code n} is {@code n + 1}.
 *
 * <p>A hot loop reads a node's word once ({@link #word}) and decodes it with the tree's
 * {@link KdTree#axisBits()}: {@link #isLeaf}, {@link #axis}, {@link #rightChild}, {@link #leafSize}.
 */
public final class Nodes {
    /** The ints a node takes in the node array. */
    static final int INTS = 3;

    private Nodes() {
    }

    /**
     * The width of a word's axis field in a {@code dimension}-D tree: wide enough for every axis and the leaf mark.
     *
     * @param dimension k, 1 .. {@link KdTree#MAX_DIMENSION}
     * @return the number of low bits of a word that hold the axis or the leaf mark
     * @throws IllegalArgumentException if {@code dimension} is out of range
     */
    public static int axisBits(int dimension) {
        if (dimension < 1 || dimension > KdTree.MAX_DIMENSION)
            throw new IllegalArgumentException("a tree has 1 to " + KdTree.MAX_DIMENSION + " dimensions, not " + dimension);
        return 32 - Integer.numberOfLeadingZeros(dimension);
    }

    /**
     * The largest node index a {@code dimension}-D tree can hold.
     *
     * @param dimension k, 1 .. {@link KdTree#MAX_DIMENSION}
     * @return the largest index a node (or leaf) of such a tree may have
     */
    public static int maxNode(int dimension) {
        return (1 << (31 - axisBits(dimension))) - 1;
    }

    /** The most references a leaf of a tree with this axis field can hold. */
    static int maxLeafSize(int axisBits) {
        return -1 >>> axisBits;
    }

    // ---- reading: the hot loops' accessors ----

    /**
     * {@return node {@code node}'s word}, which {@link #isLeaf}, {@link #axis}, {@link #rightChild} and {@link #leafSize} decode
     * @param nodes a tree's {@link KdTree#nodeArray()}
     * @param node a node's index
     */
    public static int word(int[] nodes, int node) { return nodes[INTS * node]; }

    /**
     * {@return whether a node with this word is a leaf}
     * @param word the node's {@link #word}
     * @param axisBits the tree's {@link KdTree#axisBits()}
     */
    public static boolean isLeaf(int word, int axisBits) {
        int mark = leafMark(axisBits);
        return (word & mark) == mark;
    }

    /**
     * {@return the split axis of an interior node with this word}
     * @param word the interior node's {@link #word}
     * @param axisBits the tree's {@link KdTree#axisBits()}
     */
    public static int axis(int word, int axisBits) { return word & leafMark(axisBits); }

    /**
     * {@return the split plane's position on the axis of interior node {@code node}}
     * @param nodes a tree's {@link KdTree#nodeArray()}
     * @param node an interior node's index
     */
    public static double split(int[] nodes, int node) {
        return Double.longBitsToDouble((long) nodes[INTS * node + 2] << 32 | (nodes[INTS * node + 1] & 0xffffffffL));
    }

    /**
     * {@return the left (lower) child of interior node {@code node}}: the next node in the array
     * @param node an interior node's index
     */
    public static int leftChild(int node) { return node + 1; }

    /**
     * {@return the right (upper) child of an interior node with this word}
     * @param word the interior node's {@link #word}
     * @param axisBits the tree's {@link KdTree#axisBits()}
     */
    public static int rightChild(int word, int axisBits) { return word >>> axisBits; }

    /**
     * {@return where the references of leaf {@code node} begin in the tree's {@link KdTree#refArray()}}
     * @param nodes a tree's {@link KdTree#nodeArray()}
     * @param node a leaf's index
     */
    public static int leafStart(int[] nodes, int node) { return nodes[INTS * node + 1]; }

    /**
     * {@return the number of primitive references of a leaf with this word}
     * @param word the leaf's {@link #word}
     * @param axisBits the tree's {@link KdTree#axisBits()}
     */
    public static int leafSize(int word, int axisBits) { return word >>> axisBits; }

    /** The axis field of a leaf's word: all ones. */
    private static int leafMark(int axisBits) { return (1 << axisBits) - 1; }

    // ---- writing: for KdTreeWriter ----

    /** Writes interior node {@code node}: its axis (the right child is set later) and its split position. */
    static void writeInterior(int[] nodes, int node, int axis, double xi) {
        long bits = Double.doubleToRawLongBits(xi);
        nodes[INTS * node] = axis;
        nodes[INTS * node + 1] = (int) bits;
        nodes[INTS * node + 2] = (int) (bits >>> 32);
    }

    /** Sets the right child of interior node {@code node}, keeping its axis. */
    static void writeRightChild(int[] nodes, int node, int child, int axisBits) {
        nodes[INTS * node] = (child << axisBits) | (nodes[INTS * node] & leafMark(axisBits));
    }

    /** Writes leaf {@code node}: {@code count} references from {@code first} on. */
    static void writeLeaf(int[] nodes, int node, int first, int count, int axisBits) {
        nodes[INTS * node] = (count << axisBits) | leafMark(axisBits);
        nodes[INTS * node + 1] = first;
        nodes[INTS * node + 2] = 0;
    }

    /**
     * Copies node {@code from} of {@code source} to node {@code to} of {@code target}, moving an
     * interior node's right child by {@code nodeShift} places or a leaf's references by
     * {@code refShift}: a subtree spliced into a larger tree. The split's two ints are copied as
     * they are, to the bit.
     */
    static void copyMoved(int[] source, int from, int[] target, int to, int nodeShift, int refShift, int axisBits) {
        int w = word(source, from);
        boolean leaf = isLeaf(w, axisBits);
        target[INTS * to] = leaf ? w : ((rightChild(w, axisBits) + nodeShift) << axisBits) | axis(w, axisBits);
        target[INTS * to + 1] = source[INTS * from + 1] + (leaf ? refShift : 0);
        target[INTS * to + 2] = source[INTS * from + 2];
    }
}
