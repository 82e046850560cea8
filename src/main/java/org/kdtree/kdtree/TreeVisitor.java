package org.kdtree.kdtree;

import org.kdtree.geom.Box;

/** Receives the nodes of a {@link KdTree} in depth-first order, left child first. */
public interface TreeVisitor {
    /**
     * An interior node: its voxel is cut by the plane {@code x_axis = split}.
     * The voxel box is reused between calls; copy it to keep it.
     * @param node the node's index
     * @param depth its depth; the root has depth 0
     * @param voxel its voxel
     * @param axis the split axis
     * @param split the split plane's position on {@code axis}
     */
    void interior(int node, int depth, Box voxel, int axis, double split);

    /**
     * A leaf: its primitives are the tree's {@link KdTree#ref(int) ref(from)} to {@code ref(to - 1)}
     * ({@link KdTree#leafPrimitives(int)} copies them). The voxel box is reused between calls;
     * copy it to keep it.
     * @param node the node's index
     * @param depth its depth; the root has depth 0
     * @param voxel its voxel
     * @param from the first of the leaf's references
     * @param to the end (exclusive) of the leaf's references
     */
    void leaf(int node, int depth, Box voxel, int from, int to);
}
