package org.kdtree.gui;

import java.awt.Graphics2D;
import org.kdtree.accel.AccelerationStructure;
import org.kdtree.accel.TreeStats;
import org.kdtree.bvh.Bvh;
import org.kdtree.geom.Box;
import org.kdtree.kdtree.KdTree;
import org.kdtree.shape.Scene2D;
import org.kdtree.spec.BuilderSpec;

/**
 * What one build of the workbench made, as the workbench shows it: one view per structure
 * ({@link KdTreeView}, {@link BvhView}), each with its painter, statistics, node boxes, node
 * names and tree list, so that the canvas, the stepper, the comparison and the tree view ask the
 * build and never which structure it is. The views that work on kd-trees only (the k-NN stepper,
 * the collisions) read {@link #kdTree()} and say so when it is null.
 */
interface Built {
    /**
     * {@return the view of {@code structure}, built by {@code spec}}: the one place where the
     * workbench picks a view by structure (a kd-tree's view marks the splits its lookahead kept)
     *
     * @param structure a kd-tree or a bounding volume hierarchy
     * @param spec the builder and settings it was built with
     * @throws IllegalArgumentException for a structure the workbench has no view of
     */
    static Built of(AccelerationStructure structure, BuilderSpec spec) {
        if (structure instanceof KdTree t) return KdTreeView.of(t, spec);
        if (structure instanceof Bvh b) return new BvhView(b);
        throw new IllegalArgumentException("the workbench cannot show a " + structure.kind());
    }

    /** {@return the structure as the traversals see it} */
    AccelerationStructure structure();

    /** {@return the builder's name} */
    String builderName();

    /** {@return the kd-tree, for the views that work on kd-trees only; null for another structure} */
    default KdTree kdTree() { return null; }

    /** {@return the bounds of the scene's objects} */
    default Box bounds() { return structure().bounds(); }

    /** {@return its statistics: nodes, leaves, depth, memory, expected cost under its Kt and Ki} */
    default TreeStats stats() { return structure().stats(); }

    /** {@return what its nodes are called in the statistics}: "nodes", or "nodes (boxes)" */
    String nodesLabel();

    /** {@return whether a ray's traversal tests boxes, which the stepper and the comparison then count} */
    boolean testsBoxes();

    /** {@return its number of nodes} */
    default int nodeCount() { return stats().nodes(); }

    /** {@return Kt, the cost of one node visited under its cost model} */
    default double kt() { return structure().costModel().kt(); }

    /** {@return Ki, the cost of one object tested} */
    default double ki() { return structure().costModel().ki(); }

    /** {@return whether {@code node} is a leaf} */
    boolean isLeaf(int node);

    /** {@return the region of each node, by index: a kd-tree's voxels, a hierarchy's boxes} */
    Box[] regions();

    /**
     * {@return how the steppers name a node}: "node #3 (leaf, 2 objects)", a kd-tree's
     * "node #0 (x = 5.000)", a hierarchy's "node #0 (box of children #1 and #4)"
     *
     * @param node a node's index
     */
    String nodeText(int node);

    /** "node #3 (leaf, 2 objects)". */
    static String leafText(int node, int objects) {
        return "node #" + node + " (leaf, " + objects + (objects == 1 ? " object)" : " objects)");
    }

    /** {@return the nodes of the tree list, in its own words} */
    TreeNodeView.Nodes treeNodes();

    /**
     * Paints the scene and this structure.
     *
     * @return the boxes drawn (a hierarchy's nodes; 0 for a kd-tree, drawn by its split lines)
     */
    int paint(Graphics2D g, int width, int height, Scene2D scene, ViewTransform v, TreePainter.Options o);

    /** Paints the selected node and shape over an already painted scene (see {@link TreePainter#paintSelection}). */
    void paintSelection(Graphics2D g, Scene2D scene, ViewTransform v, int selectedNode, int selectedShape);

    /** {@return the leaf under the scene point (x, y), or -1} */
    int leafAt(double x, double y);
}
