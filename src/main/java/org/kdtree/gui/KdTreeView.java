package org.kdtree.gui;

import java.awt.Graphics2D;
import java.util.Locale;
import org.kdtree.accel.AccelerationStructure;
import org.kdtree.geom.Box;
import org.kdtree.kdtree.KdTree;
import org.kdtree.shape.Scene2D;

/**
 * The workbench's view of a kd-tree: split lines by {@link TreePainter}, voxels as the nodes'
 * regions, nodes named by their plane.
 *
 * @param tree the kd-tree
 */
record KdTreeView(KdTree tree) implements Built {
    @Override public AccelerationStructure structure() { return tree; }
    @Override public String builderName() { return tree.builderName(); }
    @Override public KdTree kdTree() { return tree; }
    @Override public String nodesLabel() { return "nodes"; }
    @Override public boolean testsBoxes() { return false; }
    @Override public boolean isLeaf(int node) { return tree.isLeaf(node); }
    @Override public Box[] regions() { return StepperVoxels.of(tree); }
    @Override public TreeNodeView.Nodes treeNodes() { return new KdTreeModel(tree); }

    @Override public String nodeText(int node) {
        if (tree.isLeaf(node)) return Built.leafText(node, tree.leafSize(node));
        return "node #" + node + String.format(Locale.ROOT, " (%s = %.3f)", tree.axis(node) == 0 ? "x" : "y", tree.split(node));
    }

    @Override public int paint(Graphics2D g, int width, int height, Scene2D scene, ViewTransform v, TreePainter.Options o) {
        TreePainter.paint(g, width, height, scene, tree, v, o);
        return 0;
    }

    @Override public void paintSelection(Graphics2D g, Scene2D scene, ViewTransform v, int selectedNode, int selectedShape) {
        TreePainter.paintSelection(g, scene, tree, v, selectedNode, selectedShape);
    }

    @Override public int leafAt(double x, double y) { return TreePainter.leafAt(tree, x, y); }
}
