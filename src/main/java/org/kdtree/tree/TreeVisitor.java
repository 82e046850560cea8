package org.kdtree.tree;

import org.kdtree.geom.Box;

/** Receives the nodes of a {@link KdTree} in depth-first order, left child first. */
public interface TreeVisitor {
    /**
     * An interior node: its voxel is cut by the plane {@code x_axis = split}.
     * The voxel box is reused between calls; copy it to keep it.
     */
    void interior(int node, int depth, Box voxel, int axis, double split);

    /**
     * A leaf: its primitives are {@code refs[from .. to)}. The arrays are the tree's own; do
     * not modify them. The voxel box is reused between calls; copy it to keep it.
     */
    void leaf(int node, int depth, Box voxel, int[] refs, int from, int to);
}
