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
    private final int depth;
    private final int k;

    private SplitPlane plannedPlane;
    private double plannedCost = Double.NaN;

    /**
     * @param voxel   this node's voxel (not copied)
     * @param refs    indices of the primitives overlapping the voxel (not copied)
     * @param clipped their clipped bounds, {@code 2 k} values per reference (not copied)
     * @param depth   the root has depth 0
     */
    public BuildNode(Box voxel, int[] refs, double[] clipped, int depth) {
        this.voxel = voxel;
        this.refs = refs;
        this.clipped = clipped;
        this.depth = depth;
        this.k = voxel.dimension();
        if (clipped.length != 2 * k * refs.length)
            throw new IllegalArgumentException("need " + 2 * k + " clipped bounds per reference");
    }

    /** The voxel V of this node; do not modify. */
    public Box voxel() { return voxel; }

    /** D(V), the depth of this node; the root has depth 0. */
    public int depth() { return depth; }

    /** |T|, the number of primitives overlapping the voxel. */
    public int size() { return refs.length; }

    /** k, the dimension. */
    public int dimension() { return k; }

    /** The index of the j-th primitive of this node. */
    public int ref(int j) { return refs[j]; }

    /** Lower bound on {@code axis} of the part of the j-th primitive inside the voxel. */
    public double clippedMin(int j, int axis) { return clipped[2 * k * j + axis]; }

    /** Upper bound on {@code axis} of the part of the j-th primitive inside the voxel. */
    public double clippedMax(int j, int axis) { return clipped[2 * k * j + k + axis]; }

    /** The primitive indices (the node's own array; do not modify). */
    public int[] refs() { return refs; }

    /** The flat clipped bounds (the node's own array; do not modify). */
    public double[] clippedBounds() { return clipped; }

    /**
     * Remembers the plane a builder chose while deciding {@code terminate}, so that
     * {@code findPlane} need not search again (the SAH finds its best plane once).
     */
    public void plan(SplitPlane plane, double cost) {
        this.plannedPlane = plane;
        this.plannedCost = cost;
    }

    /** The plane remembered by {@link #plan}, or null. */
    public SplitPlane plannedPlane() { return plannedPlane; }

    /** The cost remembered by {@link #plan}, or NaN. */
    public double plannedCost() { return plannedCost; }

    /** Lets go of the arrays once the children are made, so deep recursions hold less memory. */
    protected void release() {
        refs = null;
        clipped = null;
    }
}
