package org.kdtree.gui;

import java.awt.BasicStroke;
import java.awt.BorderLayout;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.GridLayout;
import java.util.Locale;
import java.util.stream.Collectors;
import javax.swing.BorderFactory;
import javax.swing.JLabel;
import javax.swing.JPanel;
import org.kdtree.accel.AccelerationStructure;
import org.kdtree.geom.Box;
import org.kdtree.shape.Scene2D;

/**
 * The traversal stepper: replays the recorded traversal of the cast ray (see {@link
 * TraversalTrace}) one event at a time, forward, back or playing, with Algorithm 2's state in
 * labels and on the canvas (current voxel, [tMin, tMax] on the ray, tSplit, near and far
 * children, stacked voxels, objects tested, the hit). Through a bounding volume hierarchy it
 * steps through the box tests instead of the split planes: each child box tested, entered
 * (green) or missed (grey, dashed), the nearer one visited first and the other saved.
 */
final class StepperPanel extends JPanel implements CanvasOverlay {
    /** Records a ray's traversal of a tree or hierarchy: the library's traversal behind a listener. */
    public interface Recorder {
        /**
         * {@return the recorded traversal of {@code ray} through {@code structure}}
         *
         * @param structure the kd-tree or hierarchy over {@code scene}
         * @param scene the 2-D scene
         * @param ray the ray {ox, oy, dx, dy}, or null
         */
        TraversalTrace record(AccelerationStructure structure, Scene2D scene, double[] ray);
    }

    /** The model whose tree and ray are traced. */
    private final WorkbenchModel model;
    /** Records the ray's traversal. */
    private final Recorder recorder;
    /** Which event of the traversal is shown. */
    private final JLabel stepLabel = Widgets.label("step.label", "Which event of the traversal is shown");
    /** The node Algorithm 2 is at. */
    private final JLabel nodeLabel = Widgets.label("step.node", "The node Algorithm 2 is at");
    /** The ray's interval in the node, and where it meets the split plane. */
    private final JLabel intervalLabel = Widgets.label("step.interval", "The ray's interval in the node, and where it meets the split plane");
    /** Near child, far child, and which the ray visits; a hierarchy's child boxes tested. */
    private final JLabel childrenLabel = Widgets.label("step.children",
            "Near child (green), far child (blue), and which the ray visits; in a hierarchy, the child boxes tested");
    /** Far children saved for later, bottom first. */
    private final JLabel stackLabel = Widgets.label("step.stack", "Far children saved for later (purple, dashed), bottom first");
    /** Objects tested in the current leaf. */
    private final JLabel testedLabel = Widgets.label("step.tested", "Objects tested in the current leaf (red); + marks a hit closer than the best so far");
    /** The closest hit and the ray's traversal cost. */
    private final JLabel resultLabel = Widgets.label("step.result", "The closest hit and the ray's traversal cost");
    /** The recorded traversal of the current ray. */
    private TraversalTrace trace = TraversalTrace.EMPTY;
    /** The voxels of the tree shown. */
    private final StepperVoxels voxels = new StepperVoxels();
    /** The step buttons and slider; they keep the step shown. */
    private final StepControls controls = new StepControls("step", "traversal", "Ctrl", this::showStep);

    /**
     * A stepper for the ray of {@code model}, traced again on every change of tree or ray.
     *
     * @param model the workbench's model
     * @param recorder records the ray's traversal
     */
    public StepperPanel(WorkbenchModel model, Recorder recorder) {
        super(new BorderLayout());
        this.model = model;
        this.recorder = recorder;
        setBorder(BorderFactory.createTitledBorder(title(false)));
        JPanel buttons = controls.bar();
        buttons.add(stepLabel);
        JPanel labels = new JPanel(new GridLayout(0, 2, 12, 0));
        for (JLabel l : new JLabel[] {nodeLabel, intervalLabel, childrenLabel, testedLabel, stackLabel, resultLabel}) labels.add(l);
        add(buttons, BorderLayout.NORTH);
        add(labels, BorderLayout.CENTER);
        model.addListener(c -> {
            if (c != WorkbenchModel.Change.SELECTION && c != WorkbenchModel.Change.QUERY) retrace();
        });
        retrace();
    }

    /** {@return the recorded traversal of the current ray} */
    public TraversalTrace trace() { return trace; }
    /** {@return the step shown} */
    public int index() { return controls.index(); }

    /** The stepping itself (first, back, forward, last, play), for the workbench's menu and the panel's buttons. */
    StepControls controls() { return controls; }

    /** The panel's title: the kd-tree's traversal is the talk's Algorithm 2; a hierarchy's is a box traversal. */
    static String title(boolean boxes) {
        return (boxes ? "Traversal stepper (hierarchy: nearer box first)" : "Traversal stepper (Algorithm 2)")
                + " - cast a ray with the Cast ray tool (F3)";
    }

    private void retrace() {
        Built built = model.built();
        ((javax.swing.border.TitledBorder) getBorder()).setTitle(title(built.testsBoxes()));
        trace = recorder.record(built.structure(), model.scene(), model.ray());
        voxels.index(built);
        controls.reset(trace.size());
        resultLabel.setText(resultText());
    }

    /** Draws step {@code index} of the trace in the labels and on the canvas. */
    private void showStep(int index) {
        if (trace.size() == 0) {
            stepLabel.setText(model.ray() == null ? "no ray" : "no traversal");
            for (JLabel l : new JLabel[] {nodeLabel, intervalLabel, childrenLabel, stackLabel, testedLabel}) l.setText(" ");
        } else {
            TraversalTrace.Step s = trace.step(index);
            describe(s);
            // the tree view follows the step; a node skipped beyond the hit, and the end, select nothing (no objects lit as if tested)
            if (s.kind() == TraversalTrace.Kind.SKIP || s.kind() == TraversalTrace.Kind.END) model.selectNode(-1);
            else if (s.node() >= 0) model.selectNode(s.node());
        }
        Widgets.repaintWindow(this);
    }

    private void describe(TraversalTrace.Step s) {
        Built b = model.built();
        stepLabel.setText(String.format(Locale.ROOT, "step %d / %d: %s", controls.index() + 1, trace.size(), kindText(s.kind())));
        nodeLabel.setText(s.node() < 0 ? "node: -" : b.nodeText(s.node()));
        intervalLabel.setText(String.format(Locale.ROOT, "tMin = %s   tMax = %s   tSplit = %s", Widgets.num(s.tMin()), Widgets.num(s.tMax()), Widgets.num(s.tSplit())));
        childrenLabel.setText(s.near() >= 0 ? "near #" + s.near() + ", far #" + s.far() + ": " + s.visit()
                : !s.boxes().isEmpty() ? boxesText(s.boxes()) : "near / far: -");
        stackLabel.setText(stackText(s.stack()));
        testedLabel.setText("tested: " + (s.tested().isEmpty() ? "-" : s.tested().stream().map(String::valueOf)
                .collect(Collectors.joining(", "))) + (s.bestObject() >= 0 ? "   best: object " + s.bestObject() + " at t = " + Widgets.num(s.bestT()) : ""));
    }

    /** The stack, top first; only the top three entries, as the next pops take them. */
    private static String stackText(java.util.List<TraversalTrace.Entry> stack) {
        if (stack.isEmpty()) return "stack: empty";
        StringBuilder b = new StringBuilder("stack (" + stack.size() + "), top first: ");
        for (int i = stack.size() - 1; i >= Math.max(0, stack.size() - 3); i--) {
            TraversalTrace.Entry e = stack.get(i);
            b.append(i == stack.size() - 1 ? "" : ", ").append('#').append(e.node())
                    .append(" [").append(Widgets.num(e.tMin())).append(", ").append(Widgets.num(e.tMax())).append(']');
        }
        return b.append(stack.size() > 3 ? ", ..." : "").toString();
    }

    /** A hierarchy's child boxes tested at the current node: "box #1 entered [0.2, 0.5], box #2 missed". */
    private static String boxesText(java.util.List<TraversalTrace.BoxTest> boxes) {
        return boxes.stream().map(t -> "box #" + t.node() + (t.entered()
                ? " entered [" + Widgets.num(t.tMin()) + ", " + Widgets.num(t.tMax()) + "]" : " missed"))
                .collect(Collectors.joining(", "));
    }

    private String resultText() {
        if (model.ray() == null) return "result: cast a ray (drag with the Cast ray tool)";
        String hit = trace.hitObject() >= 0 ? "hit object " + trace.hitObject() + " at t = " + Widgets.num(trace.hitT()) : "no hit";
        if (model.built().testsBoxes())
            return String.format(Locale.ROOT, "result: %s  (%d nodes, %d leaves, %d box tests, %d tests)", hit, trace.nodes(),
                    trace.leaves(), trace.boxTests(), trace.tests());
        return String.format(Locale.ROOT, "result: %s  (%d nodes, %d leaves, %d tests)", hit, trace.nodes(), trace.leaves(), trace.tests());
    }

    private static String kindText(TraversalTrace.Kind k) {
        return switch (k) {
            case BEGIN -> "the ray enters the scene box";
            case MISSED_SCENE -> "the ray misses the scene box";
            case INTERIOR -> "interior node: compare tSplit with [tMin, tMax]";
            case BOX_NODE -> "interior box: test its children's boxes";
            case BOX_TEST -> "test a child's box";
            case PUSH_FAR -> "push the far child, go to the near one";
            case POP -> "pop a far child from the stack";
            case SKIP -> "pop a far child: beyond the hit, skipped";
            case LEAF -> "leaf: test its objects";
            case TEST -> "test an object";
            case MAILBOXED -> "object already tested (mailbox)";
            case END -> "done";
        };
    }

    // ---- drawing on the canvas ----

    @Override public void paint(Graphics2D g, ViewTransform v) {
        double[] ray = model.ray();
        if (ray == null || !isVisible()) return;   // another stepper's tab is up: its drawing alone
        Built built = model.built();
        double tEnd = rayEnd(built.bounds(), ray);
        g.setColor(Palette.RAY);
        g.setStroke(new BasicStroke(1.5f));
        g.draw(TreeCanvas.line(v, ray[0], ray[1], ray[0] + tEnd * ray[2], ray[1] + tEnd * ray[3]));
        StepperVoxels.dot(g, v, ray[0], ray[1], Palette.RAY, 4);
        if (trace.size() == 0 || !voxels.isOf(built)) return;
        TraversalTrace.Step s = trace.step(controls.index());
        BasicStroke dashed = new BasicStroke(2f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10, new float[] {6, 4}, 0);
        for (TraversalTrace.Entry e : s.stack()) voxels.outline(g, v, e.node(), Palette.STACKED, dashed);
        for (TraversalTrace.BoxTest b : s.boxes())
            voxels.outline(g, v, b.node(), b.entered() ? Palette.NEAR_CHILD : Palette.PRUNED, b.entered() ? new BasicStroke(2.5f) : dashed);
        if (s.near() >= 0) {
            tint(g, v, s.near(), Palette.NEAR_CHILD);
            tint(g, v, s.far(), Palette.FAR_CHILD);
        }
        if (s.node() >= 0)   // a node skipped beyond the hit: outlined as pruned, not as the node at work
            voxels.outline(g, v, s.node(), s.kind() == TraversalTrace.Kind.SKIP ? Palette.PRUNED : Palette.CURRENT_NODE,
                    s.kind() == TraversalTrace.Kind.SKIP ? dashed : new BasicStroke(3f));
        if (!Double.isNaN(s.tMin()) && !Double.isNaN(s.tMax())) {
            double a = Math.max(0, s.tMin()), b = Math.min(s.tMax(), tEnd);
            g.setColor(Palette.CURRENT_NODE);
            g.setStroke(new BasicStroke(5f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
            if (b >= a) g.draw(TreeCanvas.line(v, ray[0] + a * ray[2], ray[1] + a * ray[3], ray[0] + b * ray[2], ray[1] + b * ray[3]));
        }
        if (Double.isFinite(s.tSplit())) StepperVoxels.dot(g, v, ray[0] + s.tSplit() * ray[2], ray[1] + s.tSplit() * ray[3], Palette.FAR_CHILD, 5);
        Scene2D scene = model.scene();
        BasicStroke thick = new BasicStroke(3f);
        for (int obj : s.tested())
            if (obj < scene.size()) TreePainter.paintShape(g, scene.get(obj), v, Palette.TESTED, null, thick);
        if (s.bestObject() >= 0 && s.bestObject() < scene.size()) {
            TreePainter.paintShape(g, scene.get(s.bestObject()), v, Palette.HIT, null, thick);
            StepperVoxels.dot(g, v, ray[0] + s.bestT() * ray[2], ray[1] + s.bestT() * ray[3], Palette.HIT, 5);
        }
    }

    private void tint(Graphics2D g, ViewTransform v, int node, Color c) {
        voxels.fill(g, v, node, new Color(c.getRed(), c.getGreen(), c.getBlue(), 70));
    }

    /** Where to stop drawing the ray: past the scene box, or at the drag's end if farther. */
    static double rayEnd(Box b, double[] ray) {
        double t = 1;
        for (int cx = 0; cx < 2; cx++)
            for (int cy = 0; cy < 2; cy++) {
                double px = cx == 0 ? b.min(0) : b.max(0), py = cy == 0 ? b.min(1) : b.max(1);
                double along = ((px - ray[0]) * ray[2] + (py - ray[1]) * ray[3]) / (ray[2] * ray[2] + ray[3] * ray[3]);
                t = Math.max(t, along * 1.05);
            }
        return t;
    }
}
