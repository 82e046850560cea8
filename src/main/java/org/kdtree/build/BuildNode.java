package org.kdtree.build;

import org.kdtree.geom.Box;
import org.kdtree.geom.SplitPlane;

/**
 * A node under construction: its voxel, the primitives that overlap it, their bounds
 * clipped to the voxel, and its depth. Builders that need more (sorted event lists, say)
 * subclass it and override {@link KdTreeBuilder#split}.
 *
 * <p>The clipped bounds are kept flat: for the j-th reference, {@code k} minima then
 * {@code k} maxima, at offset {@code 2 k j}.
 */
public class BuildNode {
    private final Box voxel;
    private int[] refs;
    private double[] clipped;
    private final int base, size;
    private final int depth;
    private final int k;

    private long budget = Long.MAX_VALUE;
    /** The plane a builder of this package chose while deciding terminate, for its findPlane; null until then. */
    private SplitPlane chosen;

    /**
     * @param voxel   this node's voxel (not copied)
     * @param refs    indices of the primitives overlapping the voxel (not copied)
     * @param clipped their clipped bounds, {@code 2 k} values per reference (not copied)
     * @param depth   the root has depth 0
     */
    public BuildNode(Box voxel, int[] refs, double[] clipped, int depth) {
        this(voxel, refs, clipped, 0, refs.length, depth);
        if (clipped.length != 2 * k * refs.length)
            throw new IllegalArgumentException("need " + 2 * k + " clipped bounds per reference");
    }

    /**
     * A node whose references are the slice {@code refs[base .. base + size)} of a shared array,
     * with their clipped bounds at the same indices of {@code clipped} (a builder's scratch
     * memory; nothing is copied). A subclass that keeps its clipped bounds in another form passes
     * null and overrides {@link #clippedMin}, {@link #clippedMax} and {@link #clippedBounds}.
     * @param voxel the node's voxel V
     * @param refs the array holding the node's primitive indices
     * @param clipped the array holding their clipped bounds, {@code 2 k} per reference
     * @param base where the node's references begin in {@code refs}
     * @param size |T|, how many references the node has
     * @param depth the node's depth; the root has depth 0
     */
    protected BuildNode(Box voxel, int[] refs, double[] clipped, int base, int size, int depth) {
        this.voxel = voxel;
        this.refs = refs;
        this.clipped = clipped;
        this.base = base;
        this.size = size;
        this.depth = depth;
        this.k = voxel.dimension();
    }

    /** {@return the voxel V of this node}; do not modify it. */
    public Box voxel() { return voxel; }

    /** {@return D(V), the depth of this node}; the root has depth 0. */
    public int depth() { return depth; }

    /** {@return |T|, the number of primitives overlapping the voxel} */
    public int size() { return size; }

    /** {@return k, the dimension} */
    public int dimension() { return k; }

    /** {@return how many references this node's subtree may hold ({@link ReferenceBudget})} */
    public long budget() { return budget; }

    void budget(long references) {
        this.budget = references;
    }

    /**
     * {@return the index of the j-th primitive of this node}
     * @param j 0 .. {@link #size()} - 1
     */
    public int ref(int j) { return refs[base + j]; }

    /**
     * {@return the lower bound on {@code axis} of the part of the j-th primitive inside the voxel}
     * @param j 0 .. {@link #size()} - 1
     * @param axis the axis
     */
    public double clippedMin(int j, int axis) { return clipped[2 * k * (base + j) + axis]; }

    /**
     * {@return the upper bound on {@code axis} of the part of the j-th primitive inside the voxel}
     * @param j 0 .. {@link #size()} - 1
     * @param axis the axis
     */
    public double clippedMax(int j, int axis) { return clipped[2 * k * (base + j) + k + axis]; }

    /** {@return the primitive indices, {@link #size()} of them} (the node's own array or a copy; do not modify). */
    public int[] refs() {
        return base == 0 && refs.length == size ? refs : java.util.Arrays.copyOfRange(refs, base, base + size);
    }

    /** {@return the flat clipped bounds, {@code 2 k} per reference} (the node's own array or a copy; do not modify). */
    public double[] clippedBounds() {
        return base == 0 && clipped.length == 2 * k * size ? clipped
                : java.util.Arrays.copyOfRange(clipped, 2 * k * base, 2 * k * (base + size));
    }

    /** The array holding the references, from index {@link #base()} on (no copy, for hot loops). */
    int[] refArray() { return refs; }

    /** Where this node's references start in {@link #refArray()}. */
    int base() { return base; }

    /**
     * Remembers the plane this package's builder chose while deciding {@code terminate}, so that
     * its {@code findPlane} need not search again (the SAH finds its best plane once). Not part of
     * the contract a builder outside the package implements: it stays out of the public API.
     */
    void choose(SplitPlane plane) {
        this.chosen = plane;
    }

    /** The plane remembered by {@link #choose}, or null. */
    SplitPlane chosen() { return chosen; }

    /** Lets go of the arrays once the children are made, so deep recursions hold less memory. */
    protected void release() {
        refs = null;
        clipped = null;
    }
}
