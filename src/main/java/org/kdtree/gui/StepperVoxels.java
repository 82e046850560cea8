package org.kdtree.gui;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.geom.Ellipse2D;
import java.util.function.Supplier;
import org.kdtree.geom.Box;
import org.kdtree.kdtree.KdTree;

/**
 * The voxel of every node of the tree a stepper shows (or the box of every node of a bounding
 * volume hierarchy), indexed once per tree, and how the two steppers (traversal, k-NN search)
 * draw a node's voxel and a point.
 */
final class StepperVoxels {
    /** The voxel of each node of {@link #owner}. */
    private Box[] voxels = new Box[0];
    /** The kd-tree or build {@link #voxels} belong to. */
    private Object owner;

    /** {@return whether the voxels are those of {@code structure}, a kd-tree or a build} */
    boolean isOf(Object structure) { return owner == structure; }

    /** Indexes the voxels of {@code t} unless they already are. */
    void index(KdTree t) {
        index(t, () -> of(t));
    }

    /** Indexes the voxels or boxes of {@code b} unless they already are. */
    void index(Built b) {
        index(b, b::regions);
    }

    private void index(Object structure, Supplier<Box[]> regions) {
        if (owner == structure) return;
        voxels = regions.get();
        owner = structure;
    }

    /** {@return the voxel of {@code node}}, or null if there is no such node. */
    Box voxel(int node) { return node < 0 || node >= voxels.length ? null : voxels[node]; }

    void fill(Graphics2D g, ViewTransform v, int node, Color c) {
        Box b = voxel(node);
        if (b == null) return;
        g.setColor(c);
        g.fill(TreePainter.rect(v, b));
    }

    void outline(Graphics2D g, ViewTransform v, int node, Color c, BasicStroke stroke) {
        Box b = voxel(node);
        if (b == null) return;
        g.setColor(c);
        g.setStroke(stroke);
        g.draw(TreePainter.rect(v, b));
    }

    static void dot(Graphics2D g, ViewTransform v, double x, double y, Color c, double r) {
        g.setColor(c);
        g.fill(new Ellipse2D.Double(v.screenX(x) - r, v.screenY(y) - r, 2 * r, 2 * r));
    }

    /** The voxel of every node, indexed by node. */
    static Box[] of(KdTree tree) {
        Box[] out = new Box[tree.nodeCount()];
        tree.walk(new org.kdtree.kdtree.TreeVisitor() {
            @Override public void interior(int node, int depth, Box voxel, int axis, double split) { out[node] = voxel.copy(); }
            @Override public void leaf(int node, int depth, Box voxel, int from, int to) { out[node] = voxel.copy(); }
        });
        return out;
    }
}
