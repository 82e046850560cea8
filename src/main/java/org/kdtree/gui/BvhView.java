package org.kdtree.gui;

import java.awt.Graphics2D;
import org.kdtree.accel.AccelerationStructure;
import org.kdtree.bvh.Bvh;
import org.kdtree.bvh.BvhBuilder;
import org.kdtree.geom.Box;
import org.kdtree.shape.Scene2D;

/**
 * The workbench's view of a bounding volume hierarchy: every node's box by {@link BvhPainter},
 * the boxes as the nodes' regions, box tests counted.
 *
 * @param bvh the hierarchy
 */
record BvhView(Bvh bvh) implements Built {
    @Override public AccelerationStructure structure() { return bvh; }
    @Override public String builderName() { return BvhBuilder.NAME; }
    @Override public String nodesLabel() { return "nodes (boxes)"; }
    @Override public boolean testsBoxes() { return true; }
    @Override public boolean isLeaf(int node) { return bvh.isLeaf(node); }
    @Override public Box[] regions() { return BvhPainter.boxes(bvh); }
    @Override public TreeNodeView.Nodes treeNodes() { return new BvhTreeModel(bvh); }

    @Override public String nodeText(int node) {
        if (bvh.isLeaf(node)) return Built.leafText(node, bvh.leafSize(node));
        return "node #" + node + " (box of children #" + bvh.left(node) + " and #" + bvh.right(node) + ")";
    }

    @Override public int paint(Graphics2D g, int width, int height, Scene2D scene, ViewTransform v, TreePainter.Options o) {
        return BvhPainter.paint(g, width, height, scene, bvh, v, o);
    }

    @Override public void paintSelection(Graphics2D g, Scene2D scene, ViewTransform v, int selectedNode, int selectedShape) {
        BvhPainter.paintSelection(g, scene, bvh, v, selectedNode, selectedShape);
    }

    @Override public int leafAt(double x, double y) { return BvhPainter.leafAt(bvh, x, y); }
}
