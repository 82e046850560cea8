package org.kdtree.gui;

import java.awt.BasicStroke;
import java.awt.BorderLayout;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.GridLayout;
import java.awt.geom.Ellipse2D;
import java.util.BitSet;
import java.util.List;
import java.util.Locale;
import javax.swing.BorderFactory;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JSpinner;
import org.kdtree.collide.ShapeCollider;
import org.kdtree.geom.Box;
import org.kdtree.kdtree.KdTree;
import org.kdtree.shape.Scene2D;

/**
 * The nearest-neighbour stepper: replays the recorded search for the k objects nearest to the
 * query point (see {@link NearestTrace}) one event at a time, forward, back or playing, with the
 * search's state in labels and on the canvas: the query point, the search radius (the circle of
 * the k-th best distance), the nodes entered and pruned so far, the current node and its
 * distance bound, the object tested, the best list.
 */
final class NearestStepperPanel extends JPanel implements CanvasOverlay {
    private static final Color ENTERED = new Color(0xFF, 0xC8, 0x30, 80);
    private static final Color NEAR_TINT = new Color(0x40, 0xB0, 0x40, 70), FAR_TINT = new Color(0x40, 0x80, 0xE0, 70);
    private static final Color PRUNED_FILL = new Color(0x50, 0x50, 0x50, 45);
    private static final BasicStroke DASHED = new BasicStroke(2f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10,
            new float[] {6, 4}, 0);
    private static final BasicStroke THICK = new BasicStroke(3f), THIN = new BasicStroke(1.5f);

    /** What the stepper says while the builder is the bounding volume hierarchy's. */
    static final String KD_TREES_ONLY = "the k-NN stepper searches kd-trees: choose a kd-tree builder";
    /** The model whose scene, tree and query point are searched. */
    private final WorkbenchModel model;
    /** Which event of the search is shown. */
    private final JLabel stepLabel = Widgets.label("knn.label", "Which event of the nearest-neighbour search is shown");
    /** The node the search is at, and the distance from the query to its voxel. */
    private final JLabel nodeLabel = Widgets.label("knn.node", "The node the search is at, and the distance from the query to its voxel");
    /** The k-th best distance so far: the search radius. */
    private final JLabel radiusLabel = Widgets.label("knn.kth", "The k-th best distance so far: the search radius (dashed circle); voxels beyond it are pruned");
    /** The object tested at this step and its exact distance. */
    private final JLabel testedLabel = Widgets.label("knn.tested", "The object tested at this step (red) and its exact distance");
    /** The k best objects so far, nearest first. */
    private final JLabel bestLabel = Widgets.label("knn.best", "The k best objects so far (black), nearest first");
    /** The k nearest objects and the search's cost. */
    private final JLabel resultLabel = Widgets.label("knn.result", "The k nearest objects and the search's cost");
    /** Why a typed k is refused, or blank. */
    private final JLabel rejection = Widgets.label("knn.rejection", "Why a typed k is refused");
    /** The k searched for. */
    private final JSpinner kSpinner = LimitedSpinner.of(WorkbenchLimits.STEPPER_K, "k", 3, 1, this::reject);
    /** The recorded search of the current query. */
    private NearestTrace trace = NearestTrace.EMPTY;
    /** Nodes entered, and nodes pruned, up to the step shown. */
    private BitSet entered = new BitSet(), pruned = new BitSet();
    /** The voxels of the tree searched. */
    private final StepperVoxels voxels = new StepperVoxels();
    /** Exact distances from the query to the objects of {@link #colliderOf}. */
    private ShapeCollider collider;
    /** The scene {@link #collider} measures. */
    private Scene2D colliderOf;
    /** Scratch for the closest point of an object to the query. */
    private final double[] closest = new double[3];
    /** The step buttons and slider; they keep the step shown. */
    private final StepControls controls = new StepControls("knn", "search", "Ctrl+Shift", this::showStep);

    /**
     * A stepper for the query point of {@code model}, searched again on every change of tree or query.
     *
     * @param model the workbench's model
     */
    public NearestStepperPanel(WorkbenchModel model) {
        super(new BorderLayout());
        this.model = model;
        setBorder(BorderFactory.createTitledBorder("Nearest-neighbour stepper - place a query with the k-NN query tool (F8)"));
        JPanel buttons = controls.bar();
        buttons.add(new JLabel("k"));
        kSpinner.setName("knn.k");
        kSpinner.setToolTipText("How many nearest objects to search for; " + LimitedSpinner.allowed(WorkbenchLimits.STEPPER_K));
        kSpinner.addChangeListener(e -> retrace());
        buttons.add(kSpinner);
        buttons.add(Widgets.button("Clear", "knn.clear", "Remove the query point (Ctrl+Shift+K)", model::clearQuery));
        buttons.add(stepLabel);
        rejection.setForeground(new Color(170, 0, 0));
        buttons.add(rejection);
        JPanel labels = new JPanel(new GridLayout(0, 2, 12, 0));
        for (JLabel l : new JLabel[] {nodeLabel, radiusLabel, testedLabel, bestLabel}) labels.add(l);
        add(buttons, BorderLayout.NORTH);
        add(labels, BorderLayout.CENTER);
        add(resultLabel, BorderLayout.SOUTH);
        model.addListener(c -> {
            if (c == WorkbenchModel.Change.TREE || c == WorkbenchModel.Change.QUERY) retrace();
        });
        retrace();
    }

    /** {@return the recorded search of the current query} (empty without one). */
    public NearestTrace trace() { return trace; }

    /** {@return the step shown} */
    public int index() { return controls.index(); }

    /** {@return the k searched for} */
    public int k() { return ((Number) kSpinner.getValue()).intValue(); }

    /**
     * Sets k (within {@link WorkbenchLimits#STEPPER_K}) and searches again.
     *
     * @param k the number of neighbours
     */
    public void setK(int k) { kSpinner.setValue(WorkbenchLimits.STEPPER_K.check("k", k)); }

    /** The stepping itself (first, back, forward, last, play), for the workbench's menu and the panel's buttons. */
    StepControls controls() { return controls; }

    private void reject(String why) {
        rejection.setText(why == null ? " " : why);
    }

    private void retrace() {
        KdTree tree = model.tree();   // null under a hierarchy: the search is a kd-tree's
        trace = tree == null ? NearestTrace.EMPTY : NearestRecorder.record(tree, model.scene(), model.query(), k());
        if (colliderOf != model.scene()) {
            colliderOf = model.scene();
            collider = new ShapeCollider(colliderOf);
        }
        if (trace.size() > 0 && !voxels.isOf(tree)) {   // only with a query: a large tree's index is not free
            voxels.index(tree);
        }
        controls.reset(trace.size());
        resultLabel.setText(resultText());
    }

    /** Draws step {@code index} of the trace in the labels and on the canvas. */
    private void showStep(int index) {
        entered = trace.enteredUpTo(index);
        pruned = trace.prunedUpTo(index);
        if (trace.size() == 0) {
            stepLabel.setText(model.tree() == null ? KD_TREES_ONLY : "no query");
            for (JLabel l : new JLabel[] {nodeLabel, radiusLabel, testedLabel, bestLabel}) l.setText(" ");
        } else {
            NearestTrace.Step s = trace.step(controls.index());
            describe(s);
            if (s.node() >= 0) model.selectNode(s.node());   // the tree view follows the step
        }
        Widgets.repaintWindow(this);
    }

    private void describe(NearestTrace.Step s) {
        KdTree t = model.tree();
        stepLabel.setText(String.format(Locale.ROOT, "step %d / %d: %s", controls.index() + 1, trace.size(), kindText(s.kind())));
        String node = "node: -";
        if (s.node() >= 0) {
            node = "node #" + s.node() + (t.isLeaf(s.node())
                    ? " (leaf, " + t.leafSize(s.node()) + (t.leafSize(s.node()) == 1 ? " object)" : " objects)")
                    : String.format(Locale.ROOT, " (%s = %.3f)", t.axis(s.node()) == 0 ? "x" : "y", t.split(s.node())));
            if (!Double.isNaN(s.bound())) node += ", voxel at " + Widgets.num(s.bound());
            if (s.near() >= 0) node += ": near #" + s.near() + " first, then far #" + s.far();
        }
        nodeLabel.setText(node);
        radiusLabel.setText("k-th distance (radius): " + Widgets.num(s.kth()) + "   (" + s.best().size() + " of " + trace.k() + " found)");
        testedLabel.setText(testedText(s));
        bestLabel.setText("best: " + listText(s.best(), 6));
    }

    private static String testedText(NearestTrace.Step s) {
        return switch (s.kind()) {
            case TEST -> "tested: object " + s.object() + " at " + Widgets.num(s.distance())
                    + (s.improved() ? ": enters the best list" : Double.isInfinite(s.distance()) ? ": flat, never a neighbour"
                    : ": beyond the k-th, dropped");
            case MAILBOXED -> "tested: object " + s.object() + " was tested in another leaf (mailbox)";
            case PRUNE -> "pruned: voxel at " + Widgets.num(s.bound()) + " >= radius " + Widgets.num(s.kth());
            default -> "tested: -";
        };
    }

    private String resultText() {
        if (model.tree() == null) return "result: -";
        if (trace.size() == 0) return "result: place a query point (click with the k-NN query tool)";
        return String.format(Locale.ROOT, "result: %s  (%d nodes, %d leaves, %d pruned, %d of %d objects tested)",
                listText(trace.result(), 4), trace.nodes(), trace.leaves(), trace.pruned(), trace.tests(), model.scene().size());
    }

    /** The first {@code most} neighbours as "#object distance", then "..." if there are more. */
    static String listText(List<NearestTrace.Neighbour> list, int most) {
        if (list.isEmpty()) return "-";
        StringBuilder b = new StringBuilder();
        for (int i = 0; i < Math.min(most, list.size()); i++)
            b.append(i == 0 ? "" : ", ").append('#').append(list.get(i).object()).append(' ').append(Widgets.num(list.get(i).distance()));
        return b.append(list.size() > most ? ", ... (" + list.size() + ")" : "").toString();
    }

    private static String kindText(NearestTrace.Kind k) {
        return switch (k) {
            case BEGIN -> "start at the root";
            case INTERIOR -> "interior node: near child first";
            case LEAF -> "leaf: test its objects";
            case PRUNE -> "prune: the voxel lies beyond the radius";
            case TEST -> "test an object's distance";
            case MAILBOXED -> "object already tested (mailbox)";
            case END -> "done";
        };
    }

    // ---- drawing on the canvas ----

    @Override public void paint(Graphics2D g, ViewTransform v) {
        double[] q = model.query();
        if (q == null || !isVisible() || trace.size() == 0 || !voxels.isOf(model.tree())) return;   // hidden tab: not drawn
        NearestTrace.Step s = trace.step(controls.index());
        for (int n = entered.nextSetBit(0); n >= 0; n = entered.nextSetBit(n + 1))
            if (model.tree().isLeaf(n)) voxels.fill(g, v, n, ENTERED);
        g.setStroke(DASHED);
        for (int n = pruned.nextSetBit(0); n >= 0; n = pruned.nextSetBit(n + 1)) {
            voxels.fill(g, v, n, PRUNED_FILL);
            voxels.outline(g, v, n, Palette.PRUNED, DASHED);
        }
        if (s.near() >= 0) {
            voxels.fill(g, v, s.near(), NEAR_TINT);
            voxels.fill(g, v, s.far(), FAR_TINT);
        }
        if (s.node() >= 0) {
            Color c = s.kind() == NearestTrace.Kind.PRUNE ? Palette.PRUNED : Palette.CURRENT_NODE;
            voxels.outline(g, v, s.node(), c, THICK);
            if (!Double.isNaN(s.bound()) && voxels.voxel(s.node()) != null) {
                Box b = voxels.voxel(s.node());   // the voxel's point nearest the query: its distance is the bound
                double bx = Math.min(Math.max(q[0], b.min(0)), b.max(0)), by = Math.min(Math.max(q[1], b.min(1)), b.max(1));
                g.setColor(c);
                g.setStroke(THIN);
                g.draw(TreeCanvas.line(v, q[0], q[1], bx, by));
                StepperVoxels.dot(g, v, bx, by, c, 4);
            }
        }
        Scene2D scene = model.scene();
        g.setStroke(THIN);
        for (NearestTrace.Neighbour n : s.best()) {   // each of the best, with a spoke to its point nearest the query
            if (n.object() >= scene.size() || colliderOf != scene) continue;
            TreePainter.paintShape(g, scene.get(n.object()), v, Palette.HIT, null, THICK);
            collider.closestPoint(n.object(), q, closest);
            g.setColor(Palette.HIT);
            g.setStroke(THIN);
            g.draw(TreeCanvas.line(v, q[0], q[1], closest[0], closest[1]));
        }
        if (s.kind() == NearestTrace.Kind.TEST && s.object() < scene.size()) {
            TreePainter.paintShape(g, scene.get(s.object()), v, Palette.TESTED, null, THICK);
            if (!Double.isNaN(s.closestX())) {
                g.setColor(Palette.TESTED);
                g.setStroke(THIN);
                g.draw(TreeCanvas.line(v, q[0], q[1], s.closestX(), s.closestY()));
                StepperVoxels.dot(g, v, s.closestX(), s.closestY(), Palette.TESTED, 4);
            }
        }
        if (Double.isFinite(s.kth())) {
            double r = s.kth() * v.scale();
            g.setColor(Palette.QUERY);
            g.setStroke(DASHED);
            g.draw(new Ellipse2D.Double(v.screenX(q[0]) - r, v.screenY(q[1]) - r, 2 * r, 2 * r));
        }
        StepperVoxels.dot(g, v, q[0], q[1], Palette.QUERY, 5);
    }
}
