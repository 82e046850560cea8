package org.kdtree.gui;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.Shape;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Line2D;
import java.awt.geom.Path2D;
import java.awt.geom.Rectangle2D;
import java.util.BitSet;
import org.kdtree.geom.Box;
import org.kdtree.kdtree.KdTree;
import org.kdtree.kdtree.TreeVisitor;
import org.kdtree.shape.Scene2D;
import org.kdtree.shape.Shape2D;

/**
 * Draws a 2-D scene and its kd-tree the way the talk's figures 2-5 do: empty voxels shaded,
 * the objects, and each split line clipped to the voxel it cuts, thicker nearer the root.
 * Pure drawing into any {@link Graphics2D}, so that tests can paint into an image.
 */
final class TreePainter {
    private TreePainter() {
    }

    /** What to draw besides scene and tree. */
    public record Options(int selectedNode, int selectedShape, boolean antialias) {
        /** No selection, antialiased. */
        public static final Options PLAIN = new Options(-1, -1, true);
    }

    /**
     * {@return the pixel width of a split line at {@code depth}}: 5 at the root, down to 1.
     *
     * @param depth the depth of the node the line splits
     */
    public static float lineWidth(int depth) {
        return Math.max(1f, 5f - depth);
    }

    /** Above this many objects (or four times as many nodes), drawing is without antialiasing: a repaint must stay interactive. */
    public static final int ANTIALIAS_LIMIT = 2000;

    /**
     * Paints the background, empty voxels, selection, objects and split lines into {@code g}.
     *
     * @param g the graphics to paint into
     * @param width the width in pixels
     * @param height the height in pixels
     * @param scene the 2-D scene
     * @param tree the kd-tree over {@code scene}
     * @param v maps scene coordinates to pixels
     * @param o what to draw besides scene and tree
     */
    public static void paint(Graphics2D g, int width, int height, Scene2D scene, KdTree tree, ViewTransform v,
                             Options o) {
        paint(g, width, height, scene, tree, new BitSet(), v, o);
    }

    /**
     * Paints as {@link #paint(Graphics2D, int, int, Scene2D, KdTree, ViewTransform, Options)} does, with the
     * split lines of {@code pastMinimum} dashed in {@link Palette#LOOKAHEAD_SPLIT} and, if there are any, a
     * legend saying what they are.
     *
     * @param g the graphics to paint into
     * @param width the width in pixels
     * @param height the height in pixels
     * @param scene the 2-D scene
     * @param tree the kd-tree over {@code scene}
     * @param pastMinimum the interior nodes whose splits a lookahead kept past a local minimum
     * @param v maps scene coordinates to pixels
     * @param o what to draw besides scene and tree
     */
    public static void paint(Graphics2D g, int width, int height, Scene2D scene, KdTree tree, BitSet pastMinimum,
                             ViewTransform v, Options o) {
        boolean aa = o.antialias() && scene.size() <= ANTIALIAS_LIMIT && tree.nodeCount() <= 4 * ANTIALIAS_LIMIT;
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, aa ? RenderingHints.VALUE_ANTIALIAS_ON : RenderingHints.VALUE_ANTIALIAS_OFF);
        g.setColor(Palette.BACKGROUND);
        g.fillRect(0, 0, width, height);
        BitSet highlighted = new BitSet();
        Path2D.Double[] splits = new Path2D.Double[(int) lineWidth(0) + 1], past = new Path2D.Double[splits.length];
        Box selectedVoxel = paintVoxels(g, tree, v, o.selectedNode(), highlighted, pastMinimum, splits, past);
        paintObjects(g, scene, v, highlighted, o.selectedShape());
        paintSplits(g, splits, null);
        paintSplits(g, past, Palette.LOOKAHEAD_SPLIT);
        Box root = tree.bounds();
        if (!root.isEmpty()) {
            g.setColor(Palette.ROOT_BOX);
            g.setStroke(new BasicStroke(lineWidth(0)));
            g.draw(rect(v, root));
        }
        if (selectedVoxel != null) {
            g.setColor(Palette.HIGHLIGHT_OBJECT);
            g.setStroke(new BasicStroke(2f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10, new float[] {6, 4}, 0));
            g.draw(rect(v, selectedVoxel));
        }
        if (!pastMinimum.isEmpty()) paintLegend(g, height);
    }

    /** A dashed stroke of width {@code w}: a split kept past a local minimum. */
    private static BasicStroke dashed(float w) {
        return new BasicStroke(w, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10, new float[] {8, 5}, 0);
    }

    /** The legend of the dashed splits, at the canvas's lower left: a sample line and its words. */
    private static void paintLegend(Graphics2D g, int height) {
        int x = 8, y = height - 10, line = 28;
        int textWidth = g.getFontMetrics().stringWidth(KdTreeView.PAST_MINIMUM);
        g.setColor(new Color(255, 255, 255, 220));
        g.fillRect(x - 4, y - 14, line + textWidth + 16, 20);
        g.setColor(Palette.LOOKAHEAD_SPLIT);
        g.setStroke(dashed(3f));
        g.drawLine(x, y - 4, x + line, y - 4);
        g.setColor(Palette.SPLIT_LINE);
        g.drawString(KdTreeView.PAST_MINIMUM, x + line + 6, y);
    }

    /**
     * Draws only the selection over an already painted scene (translucent voxel, its objects, the
     * selected shape): the canvas keeps the rest in an image, so hovering stays fast on big scenes.
     * @param g the graphics to paint into
     * @param scene the 2-D scene
     * @param tree the kd-tree over {@code scene}
     * @param v maps scene coordinates to pixels
     * @param selectedNode the selected node, or -1
     * @param selectedShape the selected shape, or -1
     */
    public static void paintSelection(Graphics2D g, Scene2D scene, KdTree tree, ViewTransform v, int selectedNode,
                                      int selectedShape) {
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        if (selectedNode >= 0 && selectedNode < tree.nodeCount()) {
            Box voxel = voxelOf(tree, selectedNode);
            BitSet objects = new BitSet();
            markAll(tree, selectedNode, objects);
            Color h = Palette.HIGHLIGHT_VOXEL;
            g.setColor(new Color(h.getRed(), h.getGreen(), h.getBlue(), 150));
            g.fill(rect(v, voxel));
            BasicStroke thin = new BasicStroke(1.5f);
            for (int i = objects.nextSetBit(0); i >= 0; i = objects.nextSetBit(i + 1))
                paintShape(g, scene.get(i), v, Palette.HIGHLIGHT_OBJECT, Palette.HIGHLIGHT_OBJECT.brighter(), thin);
            g.setColor(Palette.HIGHLIGHT_OBJECT);
            g.setStroke(new BasicStroke(2f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10, new float[] {6, 4}, 0));
            g.draw(rect(v, voxel));
        }
        if (selectedShape >= 0 && selectedShape < scene.size())
            paintShape(g, scene.get(selectedShape), v, Palette.SELECTED_SHAPE, null, new BasicStroke(3f));
    }

    /**
     * One walk of the tree: shades empty leaves (integer rectangles, the fast path), finds the
     * selected node, and collects the split lines, one path per line width, into {@code splits}
     * (those of {@code pastMinimum} into {@code past}). Returns the selected node's voxel (or null).
     */
    private static Box paintVoxels(Graphics2D g, KdTree tree, ViewTransform v, int selected, BitSet highlighted,
                                   BitSet pastMinimum, Path2D.Double[] splits, Path2D.Double[] past) {
        Box[] found = new Box[1];
        for (int i = 0; i < splits.length; i++) {
            splits[i] = new Path2D.Double();
            past[i] = new Path2D.Double();
        }
        g.setColor(Palette.EMPTY_VOXEL);
        tree.walk(new TreeVisitor() {
            @Override public void interior(int node, int depth, Box voxel, int axis, double split) {
                if (node == selected) found[0] = voxel.copy();
                Path2D.Double p = (pastMinimum.get(node) ? past : splits)[(int) lineWidth(depth)];
                if (axis == 0) {
                    p.moveTo(v.screenX(split), v.screenY(voxel.min(1)));
                    p.lineTo(v.screenX(split), v.screenY(voxel.max(1)));
                } else {
                    p.moveTo(v.screenX(voxel.min(0)), v.screenY(split));
                    p.lineTo(v.screenX(voxel.max(0)), v.screenY(split));
                }
            }

            @Override public void leaf(int node, int depth, Box voxel, int from, int to) {
                if (node == selected) {
                    found[0] = voxel.copy();
                    for (int i = from; i < to; i++) highlighted.set(tree.ref(i));
                } else if (from == to) {
                    int x0 = (int) Math.round(v.screenX(voxel.min(0))), x1 = (int) Math.round(v.screenX(voxel.max(0)));
                    int y0 = (int) Math.round(v.screenY(voxel.max(1))), y1 = (int) Math.round(v.screenY(voxel.min(1)));
                    g.fillRect(x0, y0, x1 - x0, y1 - y0);
                }
            }
        });
        if (found[0] != null) {
            if (tree.isLeaf(selected)) {
                g.setColor(Palette.HIGHLIGHT_VOXEL);
                g.fill(rect(v, found[0]));
            } else {
                markAll(tree, selected, highlighted);
            }
        }
        return found[0];
    }

    private static void markAll(KdTree tree, int node, BitSet out) {
        if (tree.isLeaf(node)) {
            for (int i = tree.leafStart(node); i < tree.leafEnd(node); i++) out.set(tree.ref(i));
            return;
        }
        markAll(tree, tree.leftChild(node), out);
        markAll(tree, tree.rightChild(node), out);
    }

    /** Draws the objects: all fills as one path, all outlines as another, then the highlighted ones on top. */
    static void paintObjects(Graphics2D g, Scene2D scene, ViewTransform v, BitSet highlighted, int selected) {
        Path2D.Double fills = new Path2D.Double(Path2D.WIND_NON_ZERO, 8 * scene.size() + 8);
        Path2D.Double lines = new Path2D.Double(Path2D.WIND_NON_ZERO, 8 * scene.size() + 8);
        for (int i = 0; i < scene.size(); i++) {
            if (highlighted.get(i)) continue;
            Shape2D s = scene.get(i);
            Shape shape = outline(s, v);
            if (!(s instanceof Shape2D.Segment)) fills.append(shape, false);
            if (!(s instanceof Shape2D.Point)) lines.append(shape, false);
        }
        g.setColor(Palette.OBJECT_FILL);
        g.fill(fills);
        g.setColor(Palette.OBJECT);
        // wide strokes of a big path are slow to rasterise: one-pixel outlines for big scenes
        g.setStroke(new BasicStroke(scene.size() > ANTIALIAS_LIMIT ? 1f : 1.5f));
        g.draw(lines);
        BasicStroke thin = new BasicStroke(1.5f), thick = new BasicStroke(3f);
        for (int i = highlighted.nextSetBit(0); i >= 0; i = highlighted.nextSetBit(i + 1))
            paintShape(g, scene.get(i), v, Palette.HIGHLIGHT_OBJECT, Palette.HIGHLIGHT_OBJECT.brighter(), thin);
        if (selected >= 0 && selected < scene.size())
            paintShape(g, scene.get(selected), v, Palette.SELECTED_SHAPE, null, thick);
    }

    /**
     * Draws one shape: filled if {@code fill} is not null, then outlined.
     *
     * @param g the graphics to paint into
     * @param s the shape
     * @param v maps scene coordinates to pixels
     * @param line the outline's colour
     * @param fill the fill colour, or null
     * @param stroke the outline's stroke
     */
    public static void paintShape(Graphics2D g, Shape2D s, ViewTransform v, Color line, Color fill, BasicStroke stroke) {
        Shape shape = outline(s, v);
        boolean area = s instanceof Shape2D.Rect || s instanceof Shape2D.Triangle || s instanceof Shape2D.Point;
        if (area && fill != null) {
            g.setColor(s instanceof Shape2D.Point ? line : fill);
            g.fill(shape);
        }
        g.setColor(line);
        g.setStroke(stroke);
        g.draw(shape);
    }

    /**
     * {@return the screen outline of a shape} (a point is a small disc).
     *
     * @param s the shape
     * @param v maps scene coordinates to pixels
     */
    public static Shape outline(Shape2D s, ViewTransform v) {
        double[] c = s.coords();
        if (s instanceof Shape2D.Point) {
            double r = 3.5;
            return new Ellipse2D.Double(v.screenX(c[0]) - r, v.screenY(c[1]) - r, 2 * r, 2 * r);
        }
        if (s instanceof Shape2D.Segment)
            return new Line2D.Double(v.screenX(c[0]), v.screenY(c[1]), v.screenX(c[2]), v.screenY(c[3]));
        if (s instanceof Shape2D.Rect) {
            double x0 = v.screenX(c[0]), x1 = v.screenX(c[2]), y0 = v.screenY(c[3]), y1 = v.screenY(c[1]);
            return new Rectangle2D.Double(x0, y0, Math.max(x1 - x0, 1), Math.max(y1 - y0, 1));
        }
        Path2D.Double p = new Path2D.Double();
        p.moveTo(v.screenX(c[0]), v.screenY(c[1]));
        p.lineTo(v.screenX(c[2]), v.screenY(c[3]));
        p.lineTo(v.screenX(c[4]), v.screenY(c[5]));
        p.closePath();
        return p;
    }

    /**
     * Draws the split lines collected by {@link #paintVoxels}, thickest (nearest the root) last:
     * solid, or dashed in {@code dashedIn} if it is not null (2 px at the least, so that the dashes show).
     */
    private static void paintSplits(Graphics2D g, Path2D.Double[] byWidth, Color dashedIn) {
        g.setColor(dashedIn == null ? Palette.SPLIT_LINE : dashedIn);
        for (int w = 1; w < byWidth.length; w++) {
            g.setStroke(dashedIn == null ? new BasicStroke(w, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER) : dashed(Math.max(w, 2)));
            g.draw(byWidth[w]);
        }
    }

    /**
     * {@return the screen rectangle of a voxel}
     *
     * @param v maps scene coordinates to pixels
     * @param b the voxel
     */
    public static Rectangle2D rect(ViewTransform v, Box b) {
        double x0 = v.screenX(b.min(0)), x1 = v.screenX(b.max(0)), y0 = v.screenY(b.max(1)), y1 = v.screenY(b.min(1));
        return new Rectangle2D.Double(x0, y0, x1 - x0, y1 - y0);
    }

    /**
     * {@return the leaf whose voxel holds the scene point (x, y), or -1} outside the root voxel.
     *
     * @param tree the kd-tree
     * @param x the point's x
     * @param y the point's y
     */
    public static int leafAt(KdTree tree, double x, double y) {
        Box b = tree.bounds();
        if (b.isEmpty() || x < b.min(0) || x > b.max(0) || y < b.min(1) || y > b.max(1)) return -1;
        int node = 0;
        while (!tree.isLeaf(node)) node = (tree.axis(node) == 0 ? x : y) < tree.split(node) ? tree.leftChild(node) : tree.rightChild(node);
        return node;
    }

    /**
     * {@return the voxel of {@code node} (a new box), or null} if there is no such node.
     *
     * @param tree the kd-tree
     * @param node a node's index
     */
    public static Box voxelOf(KdTree tree, int node) {
        Box[] out = new Box[1];
        tree.walk(new TreeVisitor() {
            @Override public void interior(int n, int depth, Box voxel, int axis, double split) {
                if (n == node) out[0] = voxel.copy();
            }

            @Override public void leaf(int n, int depth, Box voxel, int from, int to) {
                if (n == node) out[0] = voxel.copy();
            }
        });
        return out[0];
    }
}
