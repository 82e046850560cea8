package org.kdtree.gui;

import java.awt.BorderLayout;
import java.awt.GridLayout;
import java.awt.event.HierarchyEvent;
import java.util.List;
import java.util.Locale;
import javax.swing.JComboBox;
import javax.swing.JLabel;
import javax.swing.JPanel;
import org.kdtree.accel.TreeStats;
import org.kdtree.shape.Scene2D;
import org.kdtree.spec.BuilderSpec;

/**
 * Three builders side by side on the workbench's scene, with the same Kt, Ki, lambda, Kmintri
 * and Kmaxdepth: each tree drawn, its statistics, and the cast ray's traversal cost in it. Each
 * column chooses its builder among all registered ones (a student's too) and the bounding volume
 * hierarchy's ({@code bvh}), whose boxes are drawn by depth and whose ray cost counts the boxes
 * tested besides the nodes and objects.
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

    /** Rebuilds the three trees (or hierarchies) and retraces the ray (done lazily, when the view is visible). */
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
     * {@return the boxes the column of {@code builder} drew last} (a hierarchy's nodes; 0 for a kd-tree) (for tests)
     *
     * @param builder the builder's name
     */
    public int boxesPainted(String builder) {
        for (Column c : columns) if (c.builder.equals(builder)) return c.canvas.boxesPainted();
        throw new IllegalArgumentException("no column shows " + builder);
    }

    /**
     * Shows {@code builder}'s tree in column {@code column} (0-based), as its builder box does.
     *
     * @param column  the column
     * @param builder a registered builder's name, or "bvh" 
     */
    public void choose(int column, String builder) {
        columns[column].chooser.setSelectedItem(builder);
    }

    /** One builder, chosen in its box: its canvas, statistics and ray cost. */
    private final class Column extends JPanel {
        private final JComboBox<String> chooser = new JComboBox<>(BuilderSpec.names().toArray(String[]::new));
        private String builder;
        private final JLabel stats = new JLabel();
        private final CompareCanvas canvas = new CompareCanvas();
        /** This column's builds, off the event thread. */
        private final BackgroundBuild builds;

        Column(int index, String initial) {
            super(new BorderLayout());
            builder = initial;
            builds = new BackgroundBuild("compare build " + index);
            chooser.setSelectedItem(initial);
            chooser.setName("compare.builder." + index);
            chooser.setToolTipText("The builder this column shows: any registered builder, a student's too, or bvh, a bounding volume hierarchy");
            chooser.addActionListener(e -> {
                builder = (String) chooser.getSelectedItem();
                label();
                if (isShowing()) update(model.scene(), model.ray());
                else stale = true;
            });
            label();
            canvas.setToolTipText("This column's tree (or hierarchy's boxes, by depth) over the same scene; the leaves the ray visits are shaded orange, "
                    + "the hierarchy's boxes it enters outlined orange");
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
            if (!builds.start(s, scene, true, o -> show(scene, ray, o)))
                stats.setText("<html>building ...</html>");
        }

        private void show(Scene2D scene, double[] ray, BackgroundBuild.Outcome o) {
            if (o.fault() != null) {
                stats.setText("<html><div style='width:300px; color:#aa0000'>" + o.fault().getMessage().replace("&", "&amp;")
                        .replace("<", "&lt;") + "<br><b>The tree shown is the previous one (stale).</b></div></html>");
                return;
            }
            Built built = o.built();
            TraversalTrace trace = recorder.record(built.structure(), scene, ray);
            stats.setText("<html>" + statistics(built, o.millis()) + rayCost(built, ray, trace) + "</html>");
            canvas.set(scene, built, ray, trace);
        }

        /** Build time, nodes, leaves, depth, references per leaf, expected cost and memory. */
        private String statistics(Built built, double ms) {
            TreeStats st = built.stats();
            return String.format(Locale.ROOT, "build time: %.2f ms<br>%s: %d, leaves: %d, empty: %d<br>"
                            + "depth: %d, refs / leaf: %.2f<br>SAH cost: %.2f, memory: %s", ms, built.nodesLabel(),
                    st.nodes(), st.leaves(), st.emptyLeaves(), st.maxDepth(), st.averageRefsPerLeaf(), st.expectedCost(),
                    StatsPanel.memory(st.memoryBytes()));
        }

        /** The cast ray's traversal: nodes, leaves, boxes and objects tested, and its cost by the structure's Kt and Ki. */
        private String rayCost(Built built, double[] ray, TraversalTrace trace) {
            if (ray == null) return "<br>ray: cast one in the 2-D build view";
            if (trace.size() == 0) return "";
            double cost = built.kt() * (trace.nodes() - trace.leaves()) + built.ki() * trace.tests();
            String boxes = built.testsBoxes() ? String.format(Locale.ROOT, "%d box tests, ", trace.boxTests()) : "";
            return String.format(Locale.ROOT, "<br><b>ray:</b> %d nodes, %d leaves, %s%d tests<br>"
                    + "ray cost (Kt per interior node + Ki per test): %.0f<br>%s", trace.nodes(), trace.leaves(), boxes,
                    trace.tests(), cost, trace.hitObject() >= 0 ? "hit object " + trace.hitObject() : "no hit");
        }
    }
}
