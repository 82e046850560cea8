package org.kdtree.gui;

import java.awt.Graphics2D;
import java.util.BitSet;
import java.util.Locale;
import org.kdtree.accel.AccelerationStructure;
import org.kdtree.geom.Box;
import org.kdtree.kdtree.KdTree;
import org.kdtree.kdtree.SahSettings;
import org.kdtree.kdtree.SplitsPastLocalMinimum;
import org.kdtree.shape.Scene2D;
import org.kdtree.spec.BuilderSpec;

/**
 * The workbench's view of a kd-tree: split lines by {@link TreePainter}, voxels as the nodes'
 * regions, nodes named by their plane, and the splits a lookahead kept past a local minimum
 * marked (drawn dashed, named so).
 *
 * @param tree the kd-tree
 * @param pastMinimum its interior nodes whose split does not beat the leaf by its own cost (empty unless built with a lookahead)
 */
record KdTreeView(KdTree tree, BitSet pastMinimum) implements Built {
    /** The words the canvas's legend and the tree view give a split kept past a local minimum. */
    static final String PAST_MINIMUM = "kept past a local minimum (lookahead)";

    /**
     * {@return the view of {@code tree}, built by {@code spec}}: with a lookahead, its splits
     * kept past a local minimum found from the tree and the lambda it was built with
     *
     * @param tree the kd-tree
     * @param spec the builder and settings it was built with
     */
    static KdTreeView of(KdTree tree, BuilderSpec spec) {
        Integer lookahead = spec.value(SahSettings.LOOKAHEAD);
        boolean marks = lookahead != null && lookahead > 0;
        return new KdTreeView(tree, marks ? SplitsPastLocalMinimum.of(tree, spec.value(SahSettings.LAMBDA)) : new BitSet());
    }

    @Override public AccelerationStructure structure() { return tree; }
    @Override public String builderName() { return tree.builderName(); }
    @Override public KdTree kdTree() { return tree; }
    @Override public String nodesLabel() { return "nodes"; }
    @Override public boolean testsBoxes() { return false; }
    @Override public boolean isLeaf(int node) { return tree.isLeaf(node); }
    @Override public Box[] regions() { return StepperVoxels.of(tree); }
    @Override public TreeNodeView.Nodes treeNodes() { return new KdTreeModel(tree, pastMinimum); }

    @Override public String nodeText(int node) {
        if (tree.isLeaf(node)) return Built.leafText(node, tree.leafSize(node));
        return "node #" + node + String.format(Locale.ROOT, " (%s = %.3f%s)", tree.axis(node) == 0 ? "x" : "y", tree.split(node),
                pastMinimum.get(node) ? ", " + PAST_MINIMUM : "");
    }

    @Override public int paint(Graphics2D g, int width, int height, Scene2D scene, ViewTransform v, TreePainter.Options o) {
        TreePainter.paint(g, width, height, scene, tree, pastMinimum, v, o);
        return 0;
    }

    @Override public void paintSelection(Graphics2D g, Scene2D scene, ViewTransform v, int selectedNode, int selectedShape) {
        TreePainter.paintSelection(g, scene, tree, v, selectedNode, selectedShape);
    }

    @Override public int leafAt(double x, double y) { return TreePainter.leafAt(tree, x, y); }
}
