package org.kdtree.gui;

import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.event.HierarchyEvent;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.Supplier;
import javax.swing.JComboBox;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JPanel;
import org.kdtree.compare.Term;
import org.kdtree.compare.TreeDistance;
import org.kdtree.compare.TreeSignature;
import org.kdtree.kdtree.KdTree;
import org.kdtree.shape.Scene2D;
import org.kdtree.shape.Shape2D;

/**
 * The talk's section 5.2 in the workbench: two 2-D scenes side by side, each with its kd-tree by
 * the Builder panel's builder and settings, the difference of their leaf depths as a heat map,
 * and the distance of their trees' signatures with its terms (docs/compare.md). Either side is
 * the 2-D build tab's scene or a built-in one; changing the builder or its settings, or the scene,
 * builds both again (off the event thread, a plug-in's builder supervised, as every build of the
 * workbench).
 */
final class CompareDataView extends JPanel {
    /** The first choice of each side: whatever the 2-D build tab shows. */
    static final String CURRENT = "The 2-D build's scene";

    private final WorkbenchModel model;
    private final Map<String, Supplier<List<Shape2D>>> builtins = BuiltinScenes.all();
    private final JComboBox<String> sourceA = sources("compareData.a"), sourceB = sources("compareData.b");
    private final JLabel terms = new JLabel(" ");
    private final Picture picture = new Picture();
    private final Side a = new Side("A"), b = new Side("B");
    /** True when scene or settings changed while the view was hidden: it refreshes when shown. */
    private boolean stale = true;

    /**
     * A view comparing two scenes' trees, built as {@code model}'s settings say.
     *
     * @param model the workbench's model
     */
    CompareDataView(WorkbenchModel model) {
        super(new BorderLayout(0, 6));
        this.model = model;
        sourceB.setSelectedItem("Clustered (200)");
        JPanel top = Widgets.row("A:", sourceA, "B:", sourceB, "both built by the 2-D build tab's Builder panel");
        terms.setName("compareData.terms");
        terms.setToolTipText("The distance of the two trees' signatures, in [0, 1], and its four terms (docs/compare.md)");
        picture.setToolTipText("Each tree in its root frame (shaded by leaf depth, red split lines), and where their leaf depths differ");
        add(top, BorderLayout.NORTH);
        add(picture, BorderLayout.CENTER);
        add(terms, BorderLayout.SOUTH);
        sourceA.addActionListener(e -> refreshIfShown());
        sourceB.addActionListener(e -> refreshIfShown());
        model.addListener(c -> {
            if (c == WorkbenchModel.Change.TREE || c == WorkbenchModel.Change.FAULT) refreshIfShown();   // a new scene or settings
        });
        addHierarchyListener(e -> {
            if ((e.getChangeFlags() & HierarchyEvent.SHOWING_CHANGED) != 0 && isShowing() && stale) refresh();
        });
    }

    private JComboBox<String> sources(String name) {
        List<String> names = new ArrayList<>(List.of(CURRENT));
        names.addAll(builtins.keySet());
        JComboBox<String> box = new JComboBox<>(names.toArray(String[]::new));
        box.setName(name);
        box.setToolTipText("The scene of this side: the 2-D build tab's, or a built-in one");
        return box;
    }

    private void refreshIfShown() {
        stale = true;
        if (isShowing()) refresh();
    }

    /** Builds both trees again from the chosen scenes and the model's settings (done lazily, when the view is visible). */
    void refresh() {
        stale = false;
        a.build(scene(sourceA));
        b.build(scene(sourceB));
    }

    private Scene2D scene(JComboBox<String> source) {
        String name = (String) source.getSelectedItem();
        return CURRENT.equals(name) ? model.scene() : new Scene2D(builtins.get(name).get());
    }

    /**
     * Chooses the scenes of both sides, as their boxes do (for tests).
     *
     * @param first  a choice of side A's box
     * @param second a choice of side B's box
     */
    void choose(String first, String second) {
        sourceA.setSelectedItem(first);
        sourceB.setSelectedItem(second);
    }

    /** {@return the distance's text}, as shown below the picture (for tests) */
    String termsText() {
        return terms.getText();
    }

    /** Shows the comparison once both sides have their tree. */
    private void compared() {
        if (a.failure != null || b.failure != null) {
            terms.setText("<html><span style='color:#aa0000'>" + escape(a.failure != null ? a.failure : b.failure) + "</span></html>");
            picture.set(null, null, null, null);
            return;
        }
        if (a.side == null || b.side == null) return;
        TreeDistance d = TreeDistance.between(a.side.signature(), b.side.signature());
        StringBuilder text = new StringBuilder(String.format(Locale.ROOT, "<html><b>distance %.4f</b> &nbsp;", d.total()));
        for (Term t : Term.values())
            text.append(String.format(Locale.ROOT, "&nbsp; %s %.3f <span style='color:#666666'>(%s)</span>", t.label(), d.term(t),
                    escape(t.help().replaceAll(" \\(.*", ""))));
        terms.setText(text.append("</html>").toString());
        picture.set(a.side, b.side, d, model.settings().builder());
    }

    private static String escape(String s) {
        return s.replace("&", "&amp;").replace("<", "&lt;");
    }

    /** One side: its builds, off the event thread, and the last tree with its signature. */
    private final class Side {
        private final String label;
        private final BackgroundBuild builds;
        private TreeComparisonPicture.Side side;
        private String failure;

        Side(String label) {
            this.label = label;
            builds = new BackgroundBuild("compare data " + label);
        }

        void build(Scene2D scene) {
            side = null;
            failure = null;
            if (scene.size() == 0) {
                failure = label + ": the scene is empty; a tree needs at least one shape";
                compared();
                return;
            }
            try {
                if (!builds.start(model.settings(), scene, true, o -> show(scene, o))) terms.setText("building ...");
            } catch (IllegalArgumentException e) {
                failure = e.getMessage();
                compared();
            }
        }

        private void show(Scene2D scene, BackgroundBuild.Outcome o) {
            KdTree tree = o.built() != null ? o.built().kdTree() : null;
            if (o.fault() != null) failure = label + ": " + o.fault().getMessage();
            else if (tree == null) failure = "Compare data compares kd-trees: choose a kd-tree builder in the Builder panel (not bvh)";
            else side = new TreeComparisonPicture.Side(label + " " + sourceName(), scene, tree, TreeSignature.of(tree));
            compared();
        }

        private String sourceName() {
            Object name = (this == a ? sourceA : sourceB).getSelectedItem();
            return CURRENT.equals(name) ? "the 2-D build's scene" : String.valueOf(name);
        }
    }

    /** The comparison's picture, scaled to fit the view. */
    private static final class Picture extends JComponent {
        private TreeComparisonPicture.Side first, second;
        private TreeDistance distance;
        private String builder;

        Picture() {
            setPreferredSize(new Dimension(TreeComparisonPicture.WIDTH * 3 / 4, TreeComparisonPicture.HEIGHT * 3 / 4));
        }

        void set(TreeComparisonPicture.Side a, TreeComparisonPicture.Side b, TreeDistance d, String builderName) {
            first = a;
            second = b;
            distance = d;
            builder = builderName;
            repaint();
        }

        /** {@return whether a comparison is shown} (for tests) */
        boolean showing() {
            return distance != null;
        }

        @Override protected void paintComponent(Graphics g0) {
            if (distance == null) return;
            Graphics2D g = (Graphics2D) g0.create();
            double scale = Math.min((double) getWidth() / TreeComparisonPicture.WIDTH, (double) getHeight() / TreeComparisonPicture.HEIGHT);
            g.setRenderingHint(RenderingHints.KEY_INTERPOLATION, RenderingHints.VALUE_INTERPOLATION_BILINEAR);
            g.scale(scale, scale);
            TreeComparisonPicture.paint(g, first, second, distance, builder);
            g.dispose();
        }
    }

    /** {@return whether the picture shows a comparison} (for tests) */
    boolean pictureShown() {
        return picture.showing();
    }
}
