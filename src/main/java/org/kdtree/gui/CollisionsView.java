package org.kdtree.gui;

import java.awt.BorderLayout;
import java.awt.Color;
import java.awt.Dimension;
import java.awt.FlowLayout;
import java.awt.Graphics2D;
import java.awt.Graphics;
import java.awt.RenderingHints;
import java.awt.event.HierarchyEvent;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Rectangle2D;
import java.awt.image.BufferedImage;
import java.util.Locale;
import java.util.Random;
import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JSpinner;
import javax.swing.Timer;
import org.kdtree.geom.Box;
import org.kdtree.kdtree.KdTree;
import org.kdtree.shape.Scene2D;

/**
 * The collisions view: balls rain into the workbench's 2-D scene and bounce off its objects under
 * gravity ({@link BallSimulation}, one swept query through the scene's tree per ball and bounce),
 * a frame per tick of a Swing timer. Per frame it shows the primitive tests the tree needed
 * against those brute force would have needed (every object per sweep). A ball that leaves the
 * scene's box is dropped again from above it.
 *
 * <p>The simulation steps on the timer, never while painting; painting draws a cached image of
 * the scene and tree, then the balls with one reused ellipse.
 */
final class CollisionsView extends JPanel {
    /** Milliseconds between frames, and the simulated time a frame advances (seconds). */
    static final int FRAME_MILLIS = 30;
    private static final double FRAME_SECONDS = FRAME_MILLIS / 1000.0;
    /** Gravity in scene extents per second squared; restitution of a bounce. */
    private static final double GRAVITY = 1.2, RESTITUTION = 0.6;
    /** Ball radius as a fraction of the scene's extent. */
    private static final double RADIUS = 0.005;
    /** How far above the scene balls start, in scene extents (the first drop is spread over it). */
    private static final double DROP_HEIGHT = 0.25;

    /** What the view says while the builder is the bounding volume hierarchy's: the balls' sweeps run through a kd-tree. */
    static final String KD_TREES_ONLY = "the balls collide through a kd-tree: choose a kd-tree builder";
    /** The model whose scene and tree the balls collide with. */
    private final WorkbenchModel model;
    /** The panel the balls and objects are drawn in. */
    private final Arena arena = new Arena();
    /** The number of balls to drop. */
    private final JSpinner count = LimitedSpinner.of(WorkbenchLimits.BALLS, "balls", 300, 50, this::reject);
    /** Starts or stops the balls. */
    private final JButton start = Widgets.button("Start", "collide.start", "Start or stop the balls (Ctrl+Shift+B)", this::toggle);
    /** Frames simulated since the balls were dropped. */
    private final JLabel frameLabel = Widgets.label("collide.frame", "Frames simulated since the balls were dropped");
    /** Ball/object tests the tree needed in the last frame. */
    private final JLabel testsLabel = Widgets.label("collide.tests", "Ball/object tests the tree needed in the last frame");
    /** Tests brute force would need in the last frame. */
    private final JLabel bruteLabel = Widgets.label("collide.brute", "Tests brute force would need in the last frame: every object per sweep");
    /** The tree's tests as a share of brute force's. */
    private final JLabel ratioLabel = Widgets.label("collide.ratio", "The tree's tests as a share of brute force's");
    /** Why a typed ball count is refused, or blank. */
    private final JLabel rejection = Widgets.label("collide.rejection", "Why a typed ball count is refused");
    /** Advances the simulation one frame per tick. */
    private final Timer timer = new Timer(FRAME_MILLIS, e -> frame());
    /** Drops the balls at random places (fixed seed: the same drop every time). */
    private final Random random = new Random(16);
    /** The balls, or null before the first drop. */
    private BallSimulation sim;
    /** The tree the balls were dropped into. */
    private KdTree simTree;
    /** The scene the balls were dropped into. */
    private Scene2D simScene;
    /** The box the balls bounce in. */
    private Box simBox;
    /** The scene's extent, which ball sizes and speeds scale with. */
    private double extent;
    /** Frames simulated since the balls were last dropped. */
    private long frames;
    /** True when the tree changed since the balls were dropped: the next start drops them again. */
    private boolean stale = true;

    /**
     * A view over the scene and tree of {@code model}; the balls are dropped when it is first shown.
     *
     * @param model the workbench's model
     */
    public CollisionsView(WorkbenchModel model) {
        super(new BorderLayout());
        this.model = model;
        JPanel controls = new JPanel(new FlowLayout(FlowLayout.LEFT, 10, 2));
        controls.add(start);
        controls.add(Widgets.button("Frame", "collide.step", "Simulate one frame (Ctrl+Shift+F)", this::stepOnce));
        controls.add(Widgets.button("Reset", "collide.reset", "Drop the balls again from above the scene (Ctrl+Shift+R)", this::reset));
        controls.add(new JLabel("balls"));
        count.setName("collide.balls");
        count.setToolTipText("How many balls fall (a change drops them again); " + LimitedSpinner.allowed(WorkbenchLimits.BALLS));
        count.addChangeListener(e -> reset());
        controls.add(count);
        for (JLabel l : new JLabel[] {frameLabel, testsLabel, bruteLabel, ratioLabel}) controls.add(l);
        rejection.setForeground(new Color(170, 0, 0));
        controls.add(rejection);
        add(controls, BorderLayout.NORTH);
        arena.setToolTipText("The scene and its tree with the balls; gravity points down");
        arena.setBorder(BorderFactory.createEtchedBorder());
        add(arena, BorderLayout.CENTER);
        model.addListener(c -> {
            if (c != WorkbenchModel.Change.TREE) return;
            stale = true;
            if (isShowing()) reset();
        });
        addHierarchyListener(e -> {
            if ((e.getChangeFlags() & HierarchyEvent.SHOWING_CHANGED) == 0) return;
            if (!isShowing()) stop();
            else if (stale) reset();
        });
    }

    /** {@return whether the balls are moving} (the timer runs). */
    public boolean running() { return timer.isRunning(); }

    /** {@return frames simulated since the balls were last dropped} */
    public long frames() { return frames; }

    /** {@return tests the tree needed in the last frame} */
    public long lastTests() { return sim == null ? 0 : sim.lastTests(); }
    /** {@return tests brute force would have needed in the last frame} */
    public long lastBruteForceTests() { return sim == null ? 0 : sim.lastBruteForceTests(); }

    /** Starts the balls, or stops them. */
    public void toggle() {
        if (timer.isRunning()) {
            stop();
            return;
        }
        if (stale || sim == null) reset();
        if (sim == null) return;   // no kd-tree to collide through
        timer.start();
        start.setText("Stop");
    }

    private void stop() {
        timer.stop();
        start.setText("Start");
    }

    /** Simulates one frame (and stops the balls if they run). */
    public void stepOnce() {
        if (timer.isRunning()) stop();
        if (stale || sim == null) reset();
        frame();
    }

    /** Drops the balls again over the current scene and tree; under a hierarchy, says that the balls need a kd-tree. */
    public void reset() {
        stale = false;
        if (model.tree() == null) {
            stop();
            sim = null;
            frames = 0;
            frameLabel.setText(KD_TREES_ONLY);
            for (JLabel l : new JLabel[] {testsLabel, bruteLabel, ratioLabel}) l.setText(" ");
            arena.sceneChanged();
            return;
        }
        simTree = model.tree();
        simScene = model.scene();
        Box b = simTree.bounds();
        if (b.isEmpty() || !b.isFinite()) b = Box.of2(0, 0, 10, 10);
        extent = Math.max(b.extent(0), b.extent(1));
        if (!(extent > 0)) extent = 10;   // a point-sized scene: the 10 x 10 window of an empty one
        simBox = b;
        int n = ((Number) count.getValue()).intValue();
        sim = new BallSimulation(simTree, simScene, n, 0, -GRAVITY * extent, RESTITUTION);
        for (int i = 0; i < n; i++) {
            sim.addBall(0, 0, 0, 0, RADIUS * extent);
            drop(i, DROP_HEIGHT);
        }
        frames = 0;
        showCounts();
        arena.sceneChanged();
    }

    /** Puts ball {@code i} somewhere above the scene's box, within {@code height} extents, at rest. */
    private void drop(int i, double height) {
        double x = simBox.min(0) + random.nextDouble() * simBox.extent(0);
        double y = simBox.max(1) + 2 * RADIUS * extent + random.nextDouble() * height * extent;
        sim.place(i, x, y, 0, 0);
    }

    /**
     * The scene's box and the room above it where balls start: a ball never rises above its start
     * (bounces lose energy), so every ball stays in the picture; at the sides and below, as far as
     * a ball goes before it is dropped again.
     */
    private Box shown() {
        double side = 0.05 * extent + RADIUS * extent;
        return Box.of2(simBox.min(0) - side, simBox.min(1) - side, simBox.max(0) + side,
                simBox.max(1) + (3 * RADIUS + DROP_HEIGHT) * extent);
    }

    /**
     * {@return the balls' union on screen, in the arena's pixels} (empty before the first drop):
     * what a test checks against the arena's size.
     */
    Rectangle2D ballsOnScreen() {
        Rectangle2D all = new Rectangle2D.Double();
        for (int i = 0; sim != null && i < sim.balls(); i++) {
            double r = Math.max(1.5, sim.radius(i) * arena.view.scale());
            Rectangle2D one = new Rectangle2D.Double(
                    arena.view.screenX(sim.x(i)) - r, arena.view.screenY(sim.y(i)) - r, 2 * r, 2 * r);
            if (i == 0) all = one; else all.add(one);
        }
        return all;
    }

    /** {@return the component the scene and balls are drawn on} */
    JComponent arena() { return arena; }

    private void frame() {
        if (sim == null) return;
        sim.step(FRAME_SECONDS);
        frames++;
        double margin = 0.05 * extent;
        for (int i = 0; i < sim.balls(); i++) {
            double x = sim.x(i), y = sim.y(i);
            if (y < simBox.min(1) - margin || x < simBox.min(0) - margin || x > simBox.max(0) + margin) drop(i, 0.1);
        }
        showCounts();
        arena.repaint();
    }

    private void showCounts() {
        long t = lastTests(), b = lastBruteForceTests();
        frameLabel.setText("frame " + frames);
        testsLabel.setText(String.format(Locale.ROOT, "tree: %,d tests", t));
        bruteLabel.setText(String.format(Locale.ROOT, "brute force: %,d tests", b));
        ratioLabel.setText(b == 0 ? "(-)" : String.format(Locale.ROOT, "(%.1f%%)", 100.0 * t / b));
    }

    private void reject(String why) {
        rejection.setText(why == null ? " " : why);
    }



    /** The scene, its tree and the balls. */
    private final class Arena extends JComponent {
        private final ViewTransform view = new ViewTransform();
        private final Ellipse2D.Double ball = new Ellipse2D.Double();
        private BufferedImage base;

        Arena() {
            setPreferredSize(new Dimension(720, 640));
        }

        void sceneChanged() {
            base = null;
            repaint();
        }

        @Override protected void paintComponent(Graphics g0) {
            int w = getWidth(), h = getHeight();
            if (w <= 0 || h <= 0) return;
            if (sim == null) {
                g0.setColor(Palette.BACKGROUND);
                g0.fillRect(0, 0, w, h);
                return;
            }
            if (base == null || base.getWidth() != w || base.getHeight() != h) {
                view.fit(shown(), w, h);
                base = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
                Graphics2D bg = base.createGraphics();
                TreePainter.paint(bg, w, h, simScene, simTree, view, TreePainter.Options.PLAIN);
                bg.dispose();
            }
            Graphics2D g = (Graphics2D) g0;
            g.drawImage(base, 0, 0, null);
            g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
            g.setColor(Palette.BALL);
            for (int i = 0; i < sim.balls(); i++) {
                double r = Math.max(1.5, sim.radius(i) * view.scale());
                ball.setFrame(view.screenX(sim.x(i)) - r, view.screenY(sim.y(i)) - r, 2 * r, 2 * r);
                g.fill(ball);
            }
        }
    }
}
