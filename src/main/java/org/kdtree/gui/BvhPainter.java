package org.kdtree.gui;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.Path2D;
import java.util.BitSet;
import org.kdtree.bvh.Bvh;
import org.kdtree.geom.Box;
import org.kdtree.shape.Scene2D;

/**
 * Draws a 2-D scene and its bounding volume hierarchy: every node's box outlined, thicker nearer
 * the root ({@link TreePainter#lineWidth}), an interior box in a grey by its depth
 * ({@link Palette#bvhDepth}), a leaf's in teal ({@link Palette#BVH_LEAF_LINE}) and tinted, one
 * translucent fill per leaf, so that where sibling boxes overlap the tint is darker and both
 * outlines stay in sight. Outlines are drawn root first, so that a child's line lies over its
 * parent's where they share an edge. Pure drawing into any {@link Graphics2D}, like
 * {@link TreePainter}, so that tests can paint into an image.
 */
final class BvhPainter {
    private BvhPainter() {
    }

    /**
     * Paints the background, the leaves' tints, the selected box, the objects and every node's box.
     *
     * @param g      the graphics to paint into
     * @param width  the width in pixels
     * @param height the height in pixels
     * @param scene  the 2-D scene
     * @param bvh    the hierarchy over {@code scene}
     * @param v      maps scene coordinates to pixels
     * @param o      what to draw besides scene and hierarchy
     * @return the number of boxes drawn: every node whose box is not empty
     */
    static int paint(Graphics2D g, int width, int height, Scene2D scene, Bvh bvh, ViewTransform v, TreePainter.Options o) {
        boolean aa = o.antialias() && scene.size() <= TreePainter.ANTIALIAS_LIMIT && bvh.nodeCount() <= 4 * TreePainter.ANTIALIAS_LIMIT;
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, aa ? RenderingHints.VALUE_ANTIALIAS_ON : RenderingHints.VALUE_ANTIALIAS_OFF);
        g.setColor(Palette.BACKGROUND);
        g.fillRect(0, 0, width, height);
        paintLeafTints(g, bvh, v);
        BitSet highlighted = new BitSet();
        int selected = o.selectedNode() >= 0 && o.selectedNode() < bvh.nodeCount() ? o.selectedNode() : -1;
        if (selected >= 0) {
            g.setColor(Palette.HIGHLIGHT_VOXEL);
            g.fill(TreePainter.rect(v, bvh.nodeBounds(selected)));
            markAll(bvh, selected, highlighted);
        }
        TreePainter.paintObjects(g, scene, v, highlighted, o.selectedShape());
        int drawn = paintOutlines(g, bvh, v);
        if (selected >= 0) outlineSelected(g, v, bvh.nodeBounds(selected));
        paintPointsOnTop(g, scene, v, highlighted);
        return drawn;
    }

    /**
     * Draws the scene's points again over the boxes: a point's box is the point itself, and its
     * outline (and its parents', thicker) would hide it.
     */
    static void paintPointsOnTop(Graphics2D g, Scene2D scene, ViewTransform v, BitSet highlighted) {
        BasicStroke ring = new BasicStroke(1.5f);
        for (int i = 0; i < scene.size(); i++) {
            if (!(scene.get(i) instanceof org.kdtree.shape.Shape2D.Point p)) continue;
            java.awt.geom.Ellipse2D.Double dot = new java.awt.geom.Ellipse2D.Double(v.screenX(p.x()) - 4, v.screenY(p.y()) - 4, 8, 8);
            g.setColor(highlighted.get(i) ? Palette.HIGHLIGHT_OBJECT : Palette.OBJECT_FILL);
            g.fill(dot);
            g.setColor(highlighted.get(i) ? Palette.HIGHLIGHT_OBJECT.darker() : Palette.OBJECT);
            g.setStroke(ring);
            g.draw(dot);
        }
    }

    /**
     * Draws only the selection over an already painted scene: the selected node's box, translucent,
     * the objects under it and the selected shape (the canvas keeps the rest in an image).
     *
     * @param g             the graphics to paint into
     * @param scene         the 2-D scene
     * @param bvh           the hierarchy over {@code scene}
     * @param v             maps scene coordinates to pixels
     * @param selectedNode  the selected node, or -1
     * @param selectedShape the selected shape, or -1
     */
    static void paintSelection(Graphics2D g, Scene2D scene, Bvh bvh, ViewTransform v, int selectedNode, int selectedShape) {
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        if (selectedNode >= 0 && selectedNode < bvh.nodeCount()) {
            Box box = bvh.nodeBounds(selectedNode);
            Color h = Palette.HIGHLIGHT_VOXEL;
            g.setColor(new Color(h.getRed(), h.getGreen(), h.getBlue(), 150));
            g.fill(TreePainter.rect(v, box));
            BitSet objects = new BitSet();
            markAll(bvh, selectedNode, objects);
            BasicStroke thin = new BasicStroke(1.5f);
            for (int i = objects.nextSetBit(0); i >= 0 && i < scene.size(); i = objects.nextSetBit(i + 1))
                TreePainter.paintShape(g, scene.get(i), v, Palette.HIGHLIGHT_OBJECT, Palette.HIGHLIGHT_OBJECT.brighter(), thin);
            outlineSelected(g, v, box);
        }
        if (selectedShape >= 0 && selectedShape < scene.size())
            TreePainter.paintShape(g, scene.get(selectedShape), v, Palette.SELECTED_SHAPE, null, new BasicStroke(3f));
    }

    /**
     * {@return the smallest leaf whose box holds the scene point (x, y), or -1}: boxes may
     * overlap, and the smallest is the one the eye picks out under the mouse
     *
     * @param bvh the hierarchy
     * @param x   the point's x
     * @param y   the point's y
     */
    static int leafAt(Bvh bvh, double x, double y) {
        int best = -1;
        double bestArea = Double.POSITIVE_INFINITY;
        int[] stack = new int[bvh.maxDepth() + 2];
        int sp = 0;
        if (holds(bvh, 0, x, y)) stack[sp++] = 0;
        while (sp > 0) {
            int n = stack[--sp];
            if (bvh.isLeaf(n)) {
                double area = (bvh.max(n, 0) - bvh.min(n, 0)) * (bvh.max(n, 1) - bvh.min(n, 1));
                if (area < bestArea) {
                    best = n;
                    bestArea = area;
                }
                continue;
            }
            // each node holds its children, so at most one child per level is pending besides the path
            if (holds(bvh, bvh.left(n), x, y)) stack[sp++] = bvh.left(n);
            if (holds(bvh, bvh.right(n), x, y)) stack[sp++] = bvh.right(n);
        }
        return best;
    }

    /** {@return each node's box, by index} (the steppers' regions) */
    static Box[] boxes(Bvh bvh) {
        Box[] out = new Box[bvh.nodeCount()];
        for (int n = 0; n < out.length; n++) out[n] = bvh.nodeBounds(n);
        return out;
    }

    /** {@return each node's depth, by index}: children follow their parent in the binary layout */
    static int[] depths(Bvh bvh) {
        int[] depth = new int[bvh.nodeCount()];
        for (int n = 0; n < depth.length; n++)
            if (!bvh.isLeaf(n)) depth[bvh.left(n)] = depth[bvh.right(n)] = depth[n] + 1;
        return depth;
    }

    private static boolean holds(Bvh bvh, int n, double x, double y) {
        return x >= bvh.min(n, 0) && x <= bvh.max(n, 0) && y >= bvh.min(n, 1) && y <= bvh.max(n, 1);
    }

    /** Tints each leaf's box on its own, so that overlapping leaves show darker where they overlap. */
    private static void paintLeafTints(Graphics2D g, Bvh bvh, ViewTransform v) {
        g.setColor(Palette.BVH_LEAF);
        for (int n = 0; n < bvh.nodeCount(); n++) {
            if (!bvh.isLeaf(n)) continue;
            Box b = bvh.nodeBounds(n);
            if (!b.isEmpty()) g.fill(TreePainter.rect(v, b));
        }
    }

    /** Outlines every box, two paths per depth (interior boxes, leaves), the root's first; returns the boxes drawn. */
    private static int paintOutlines(Graphics2D g, Bvh bvh, ViewTransform v) {
        int[] depth = depths(bvh);
        Path2D.Double[] interiors = new Path2D.Double[bvh.maxDepth() + 1], leaves = new Path2D.Double[bvh.maxDepth() + 1];
        int drawn = 0;
        for (int n = 0; n < depth.length; n++) {
            Box b = bvh.nodeBounds(n);
            if (b.isEmpty()) continue;
            Path2D.Double[] paths = bvh.isLeaf(n) ? leaves : interiors;
            if (paths[depth[n]] == null) paths[depth[n]] = new Path2D.Double();
            paths[depth[n]].append(TreePainter.rect(v, b), false);
            drawn++;
        }
        for (int d = 0; d < interiors.length; d++) {
            BasicStroke stroke = new BasicStroke(TreePainter.lineWidth(d), BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER);
            draw(g, interiors[d], Palette.bvhDepth(d), stroke);
            draw(g, leaves[d], Palette.BVH_LEAF_LINE, stroke);
        }
        return drawn;
    }

    private static void draw(Graphics2D g, Path2D.Double path, Color c, BasicStroke stroke) {
        if (path == null) return;
        g.setColor(c);
        g.setStroke(stroke);
        g.draw(path);
    }

    private static void outlineSelected(Graphics2D g, ViewTransform v, Box box) {
        g.setColor(Palette.HIGHLIGHT_OBJECT);
        g.setStroke(new BasicStroke(2f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10, new float[] {6, 4}, 0));
        g.draw(TreePainter.rect(v, box));
    }

    /** Marks every object in the leaves under {@code node}. */
    private static void markAll(Bvh bvh, int node, BitSet out) {
        if (bvh.isLeaf(node)) {
            for (int r = bvh.leafStart(node); r < bvh.leafStart(node) + bvh.leafSize(node); r++) out.set(bvh.primitive(r));
            return;
        }
        markAll(bvh, bvh.left(node), out);
        markAll(bvh, bvh.right(node), out);
    }
}
