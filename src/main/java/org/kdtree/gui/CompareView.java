package org.kdtree.gui;

import java.awt.BasicStroke;
import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.GridLayout;
import java.awt.event.HierarchyEvent;
import java.util.List;
import java.util.Locale;
import javax.swing.JComboBox;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JPanel;
import org.kdtree.build.BuilderSpec;
import org.kdtree.build.Builders;
import org.kdtree.shape.Scene2D;
import org.kdtree.tree.KdTree;
import org.kdtree.tree.TreeStats;

/**
 * Three builders side by side on the workbench's scene, with the same Kt, Ki, lambda, Kmintri
 * and Kmaxdepth: each tree drawn, its statistics, and the cast ray's traversal cost in it. Each
 * column chooses its builder among all registered ones (a student's too).
 */
final class CompareView extends JPanel {
    /** The builders the columns show at first, in column order. */
    public static final List<String> DEFAULT_BUILDERS = List.of("median-plane", "object-median", "sah");

    /** The model whose scene, ray and settings the columns use. */
    private final WorkbenchModel model;
    /** Records a ray's traversal in each column's tree. */
    private final StepperPanel.Recorder recorder;
    /** One column per compared builder. */
    private final Column[] columns = new Column[DEFAULT_BUILDERS.size()];
    /** True when scene, ray or settings changed while the view was hidden: it refreshes when shown. */
    private boolean stale = true;

    /**
     * A view comparing the builders on the scene and ray of {@code model}.
     *
     * @param model the workbench's model
     * @param recorder records the ray's traversal in each tree
     */
    public CompareView(WorkbenchModel model, StepperPanel.Recorder recorder) {
        super(new GridLayout(1, DEFAULT_BUILDERS.size(), 6, 0));
        this.model = model;
        this.recorder = recorder;
        for (int i = 0; i < columns.length; i++) {
            columns[i] = new Column(i, DEFAULT_BUILDERS.get(i));
            add(columns[i]);
        }
        model.addListener(c -> {
            if (c != WorkbenchModel.Change.SELECTION && c != WorkbenchModel.Change.QUERY) {
                stale = true;
                if (isShowing()) refresh();
            }
        });
        addHierarchyListener(e -> {
            if ((e.getChangeFlags() & HierarchyEvent.SHOWING_CHANGED) != 0 && isShowing() && stale) refresh();
        });
    }

    /** Rebuilds the three trees and retraces the ray (done lazily, when the view is visible). */
    public void refresh() {
        stale = false;
        Scene2D scene = model.scene();
        double[] ray = model.ray();
        for (Column c : columns) c.update(scene, ray);
    }

    /**
     * {@return the statistics text of a builder's column} (for tests).
     *
     * @param builder the builder's name
     */
    public String statsText(String builder) {
        for (Column c : columns) if (c.builder.equals(builder)) return c.stats.getText();
        throw new IllegalArgumentException("no column shows " + builder);
    }

    /**
     * Shows {@code builder}'s tree in column {@code column} (0-based), as its builder box does.
     *
     * @param column  the column
     * @param builder a registered builder's name
     */
    public void choose(int column, String builder) {
        columns[column].chooser.setSelectedItem(builder);
    }

    /** One builder, chosen in its box: its canvas, statistics and ray cost. */
    private final class Column extends JPanel {
        private final JComboBox<String> chooser = new JComboBox<>(Builders.names().toArray(String[]::new));
        private String builder;
        private final JLabel stats = new JLabel();
        private final Mini canvas = new Mini();
        /** This column's builds, off the event thread. */
        private final BackgroundBuild builds;

        Column(int index, String initial) {
            super(new BorderLayout());
            builder = initial;
            builds = new BackgroundBuild("compare build " + index);
            chooser.setSelectedItem(initial);
            chooser.setName("compare.builder." + index);
            chooser.setToolTipText("The builder this column shows: any registered builder, a student's too");
            chooser.addActionListener(e -> {
                builder = (String) chooser.getSelectedItem();
                label();
                if (isShowing()) update(model.scene(), model.ray());
                else stale = true;
            });
            label();
            canvas.setToolTipText("This column's tree over the same scene; the leaves the ray visits are shaded orange");
            add(chooser, BorderLayout.NORTH);
            add(canvas, BorderLayout.CENTER);
            add(stats, BorderLayout.SOUTH);
        }

        /** Names the statistics after the builder shown (tests find them by it). */
        private void label() {
            stats.setName("compare." + builder);
            stats.setToolTipText("Statistics of the " + builder + " tree, and the cast ray's traversal in it");
        }

        /** Builds this column's tree off the event thread (waiting for it briefly, as the model does), then shows it. */
        void update(Scene2D scene, double[] ray) {
            BuilderSpec s = model.settings().forBuilder(builder);
            if (!builds.start(s.create(), scene, true, o -> show(scene, ray, o)))
                stats.setText("<html>building ...</html>");
        }

        private void show(Scene2D scene, double[] ray, BackgroundBuild.Outcome o) {
            if (o.fault() != null) {
                stats.setText("<html><div style='width:300px; color:#aa0000'>" + o.fault().getMessage().replace("&", "&amp;")
                        .replace("<", "&lt;") + "<br><b>The tree shown is the previous one (stale).</b></div></html>");
                return;
            }
            KdTree tree = o.tree();
            double ms = o.millis();
            TraversalTrace trace = recorder.record(tree, scene, ray);
            TreeStats st = tree.stats();
            StringBuilder b = new StringBuilder("<html>");
            b.append(String.format(Locale.ROOT, "build time: %.2f ms<br>nodes: %d, leaves: %d, empty: %d<br>"
                            + "depth: %d, refs / leaf: %.2f<br>SAH cost: %.2f", ms, st.nodes(), st.leaves(), st.emptyLeaves(),
                    st.maxDepth(), st.averageRefsPerLeaf(), st.expectedCost()));
            if (ray != null && trace.size() > 0) {
                double cost = tree.costModel().kt() * (trace.nodes() - trace.leaves()) + tree.costModel().ki() * trace.tests();
                b.append(String.format(Locale.ROOT, "<br><b>ray:</b> %d nodes, %d leaves, %d tests<br>"
                        + "ray cost (Kt per interior node + Ki per test): %.0f<br>%s", trace.nodes(), trace.leaves(),
                        trace.tests(), cost, trace.hitObject() >= 0 ? "hit object " + trace.hitObject() : "no hit"));
            } else if (ray == null) {
                b.append("<br>ray: cast one in the 2-D build view");
            }
            stats.setText(b.append("</html>").toString());
            canvas.set(scene, tree, ray, trace);
        }
    }

    /** A canvas without interaction, fitted to the scene. */
    private static final class Mini extends JComponent {
        private Scene2D scene;
        private KdTree tree;
        private double[] ray;
        private TraversalTrace trace;
        private org.kdtree.geom.Box[] voxels;

        Mini() {
            setPreferredSize(new Dimension(360, 360));
        }

        void set(Scene2D s, KdTree t, double[] r, TraversalTrace tr) {
            scene = s;
            tree = t;
            ray = r;
            trace = tr;
            voxels = r == null ? null : StepperVoxels.of(t);
            repaint();
        }

        @Override protected void paintComponent(Graphics g0) {
            if (tree == null) return;
            Graphics2D g = (Graphics2D) g0.create();
            ViewTransform v = new ViewTransform().fit(tree.bounds(), getWidth(), getHeight());
            TreePainter.paint(g, getWidth(), getHeight(), scene, tree, v, TreePainter.Options.PLAIN);
            if (ray != null) {
                // the leaves the ray visited: what it paid for in this tree
                java.awt.Color c = Palette.CURRENT_NODE;
                g.setColor(new java.awt.Color(c.getRed(), c.getGreen(), c.getBlue(), 90));
                for (TraversalTrace.Step st : trace.steps())
                    if (st.kind() == TraversalTrace.Kind.LEAF && voxels[st.node()] != null) g.fill(TreePainter.rect(v, voxels[st.node()]));
                double end = StepperPanel.rayEnd(tree.bounds(), ray);
                g.setColor(Palette.RAY);
                g.setStroke(new BasicStroke(2f));
                g.draw(TreeCanvas.line(v, ray[0], ray[1], ray[0] + end * ray[2], ray[1] + end * ray[3]));
                if (trace.hitObject() >= 0) {
                    TreePainter.paintShape(g, scene.get(trace.hitObject()), v, Palette.HIT, null, new BasicStroke(3f));
                    double hx = v.screenX(ray[0] + trace.hitT() * ray[2]), hy = v.screenY(ray[1] + trace.hitT() * ray[3]);
                    g.fill(new java.awt.geom.Ellipse2D.Double(hx - 4, hy - 4, 8, 8));
                }
            }
            g.dispose();
        }
    }
}
