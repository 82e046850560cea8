package org.kdtree.gui;

import java.awt.Graphics2D;
import java.util.Locale;
import java.util.Objects;
import org.kdtree.accel.AccelerationStructure;
import org.kdtree.accel.TreeStats;
import org.kdtree.bvh.Bvh;
import org.kdtree.bvh.BvhBuilder;
import org.kdtree.geom.Box;
import org.kdtree.kdtree.KdTree;
import org.kdtree.shape.Scene2D;

/**
 * What one build of the workbench made: a kd-tree, or a bounding volume hierarchy when the
 * builder is {@value BvhBuilder#NAME} (exactly one of the two is set). The views that draw,
 * count or step through either structure ask it here, so that each of them chooses the kd-tree's
 * or the hierarchy's painter, statistics and node boxes in one place; the views that work on
 * kd-trees only (the k-NN stepper, the collisions) read {@link #tree()} and say so when it is null.
 *
 * @param tree the kd-tree, or null
 * @param bvh  the bounding volume hierarchy, or null
 */
record Built(KdTree tree, Bvh bvh) {
    /** Exactly one structure. */
    Built {
        if ((tree == null) == (bvh == null)) throw new IllegalArgumentException("a build makes a kd-tree or a hierarchy, one of them");
    }

    /** {@return a kd-tree's build} */
    static Built of(KdTree tree) { return new Built(Objects.requireNonNull(tree, "tree"), null); }

    /** {@return a hierarchy's build} */
    static Built of(Bvh bvh) { return new Built(null, Objects.requireNonNull(bvh, "bvh")); }

    /** {@return whether it is a bounding volume hierarchy} */
    boolean isBvh() { return bvh != null; }

    /** {@return the builder's name ("bvh" for the hierarchy)} */
    String builderName() { return isBvh() ? BvhBuilder.NAME : tree.builderName(); }

    /** {@return the structure as the traversals see it} (a new view of a kd-tree each time: compare builds, not these) */
    AccelerationStructure structure() { return isBvh() ? bvh : tree; }

    /** {@return the bounds of the scene's objects} */
    Box bounds() { return isBvh() ? bvh.bounds() : tree.bounds(); }

    /** {@return its statistics: nodes, leaves, depth, memory, expected cost under its Kt and Ki} */
    TreeStats stats() { return isBvh() ? bvh.stats() : tree.stats(); }

    /** {@return its number of nodes} */
    int nodeCount() { return isBvh() ? bvh.nodeCount() : tree.nodeCount(); }

    /** {@return Kt, the cost of one node visited under its cost model} */
    double kt() { return isBvh() ? bvh.costModel().kt() : tree.costModel().kt(); }

    /** {@return Ki, the cost of one object tested} */
    double ki() { return isBvh() ? bvh.costModel().ki() : tree.costModel().ki(); }

    /** {@return whether {@code node} is a leaf} */
    boolean isLeaf(int node) { return isBvh() ? bvh.isLeaf(node) : tree.isLeaf(node); }

    /** {@return the region of each node, by index: a kd-tree's voxels, a hierarchy's boxes} */
    Box[] regions() { return isBvh() ? BvhPainter.boxes(bvh) : StepperVoxels.of(tree); }

    /**
     * {@return how the steppers name a node}: "node #3 (leaf, 2 objects)", a kd-tree's
     * "node #0 (x = 5.000)", a hierarchy's "node #0 (box)"
     *
     * @param node a node's index
     */
    String nodeText(int node) {
        if (isLeaf(node)) {
            int n = isBvh() ? bvh.leafSize(node) : tree.leafSize(node);
            return "node #" + node + " (leaf, " + n + (n == 1 ? " object)" : " objects)");
        }
        if (isBvh()) return "node #" + node + " (box of children #" + bvh.left(node) + " and #" + bvh.right(node) + ")";
        return "node #" + node + String.format(Locale.ROOT, " (%s = %.3f)", tree.axis(node) == 0 ? "x" : "y", tree.split(node));
    }

    /**
     * Paints the scene and this structure: a kd-tree by {@link TreePainter}, a hierarchy by {@link BvhPainter}.
     *
     * @return the boxes drawn (a hierarchy's nodes; 0 for a kd-tree, drawn by its split lines)
     */
    int paint(Graphics2D g, int width, int height, Scene2D scene, ViewTransform v, TreePainter.Options o) {
        if (isBvh()) return BvhPainter.paint(g, width, height, scene, bvh, v, o);
        TreePainter.paint(g, width, height, scene, tree, v, o);
        return 0;
    }

    /** Paints the selected node and shape over an already painted scene (see {@link TreePainter#paintSelection}). */
    void paintSelection(Graphics2D g, Scene2D scene, ViewTransform v, int selectedNode, int selectedShape) {
        if (isBvh()) BvhPainter.paintSelection(g, scene, bvh, v, selectedNode, selectedShape);
        else TreePainter.paintSelection(g, scene, tree, v, selectedNode, selectedShape);
    }

    /** {@return the leaf under the scene point (x, y), or -1}: a hierarchy's smallest leaf box there */
    int leafAt(double x, double y) {
        return isBvh() ? BvhPainter.leafAt(bvh, x, y) : TreePainter.leafAt(tree, x, y);
    }
}
