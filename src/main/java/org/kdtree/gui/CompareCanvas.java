package org.kdtree.gui;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Dimension;
import java.awt.Graphics2D;
import java.awt.Graphics;
import java.awt.geom.Ellipse2D;
import javax.swing.JComponent;
import org.kdtree.geom.Box;
import org.kdtree.shape.Scene2D;

/**
 * A compare column's canvas, without interaction, fitted to the scene: the tree (or the
 * hierarchy's boxes by depth), the leaves the cast ray visited shaded (and the hierarchy's
 * interior boxes it entered outlined), the ray and its hit.
 */
final class CompareCanvas extends JComponent {
    private Scene2D scene;
    private Built built;
    private double[] ray;
    private TraversalTrace trace;
    /** The region of each node, indexed only when there is a ray. */
    private Box[] regions;
    /** The boxes drawn by the last paint (a hierarchy's nodes; 0 for a kd-tree). */
    private int boxesPainted;

    CompareCanvas() {
        setPreferredSize(new Dimension(360, 360));
    }

    /**
     * Shows a build and the ray's traversal of it.
     *
     * @param s  the scene
     * @param b  the kd-tree or hierarchy over it
     * @param r  the ray {ox, oy, dx, dy}, or null
     * @param tr the ray's recorded traversal
     */
    void set(Scene2D s, Built b, double[] r, TraversalTrace tr) {
        scene = s;
        built = b;
        ray = r;
        trace = tr;
        regions = r == null ? null : b.regions();
        repaint();
    }

    /** {@return the boxes drawn by the last paint} (a hierarchy's nodes; 0 for a kd-tree, drawn by its split lines) */
    int boxesPainted() { return boxesPainted; }

    @Override protected void paintComponent(Graphics g0) {
        if (built == null) return;
        Graphics2D g = (Graphics2D) g0.create();
        ViewTransform v = new ViewTransform().fit(built.bounds(), getWidth(), getHeight());
        boxesPainted = built.paint(g, getWidth(), getHeight(), scene, v, TreePainter.Options.PLAIN);
        if (ray != null) paintRay(g, v);
        g.dispose();
    }

    /** The leaves and boxes the ray visited (what it paid for in this structure), the ray and its hit. */
    private void paintRay(Graphics2D g, ViewTransform v) {
        Color c = Palette.CURRENT_NODE, shade = new Color(c.getRed(), c.getGreen(), c.getBlue(), 90);
        g.setStroke(new BasicStroke(2f));
        for (TraversalTrace.Step st : trace.steps()) {
            boolean leaf = st.kind() == TraversalTrace.Kind.LEAF, box = st.kind() == TraversalTrace.Kind.BOX_NODE;
            if (!(leaf || box) || regions[st.node()] == null) continue;
            g.setColor(leaf ? shade : c);
            if (leaf) g.fill(TreePainter.rect(v, regions[st.node()]));
            else g.draw(TreePainter.rect(v, regions[st.node()]));
        }
        double end = StepperPanel.rayEnd(built.bounds(), ray);
        g.setColor(Palette.RAY);
        g.setStroke(new BasicStroke(2f));
        g.draw(TreeCanvas.line(v, ray[0], ray[1], ray[0] + end * ray[2], ray[1] + end * ray[3]));
        if (trace.hitObject() >= 0) {
            TreePainter.paintShape(g, scene.get(trace.hitObject()), v, Palette.HIT, null, new BasicStroke(3f));
            double hx = v.screenX(ray[0] + trace.hitT() * ray[2]), hy = v.screenY(ray[1] + trace.hitT() * ray[3]);
            g.fill(new Ellipse2D.Double(hx - 4, hy - 4, 8, 8));
        }
    }
}
