package org.kdtree.gui;

import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.event.ActionEvent;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.io.IOException;
import java.nio.file.Path;
import javax.swing.AbstractAction;
import javax.swing.Action;
import javax.swing.BorderFactory;
import javax.swing.BoxLayout;
import javax.swing.ButtonGroup;
import javax.swing.JComponent;
import javax.swing.JFileChooser;
import javax.swing.JFrame;
import javax.swing.JMenu;
import javax.swing.JMenuBar;
import javax.swing.JOptionPane;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JSplitPane;
import javax.swing.JTabbedPane;
import javax.swing.JToggleButton;
import javax.swing.JToolBar;
import javax.swing.KeyStroke;
import javax.swing.SwingUtilities;
import javax.swing.filechooser.FileNameExtensionFilter;
import org.kdtree.examples.CentreMidpointBuilder;
import org.kdtree.io.FileKind;
import org.kdtree.spec.BuilderSpec;
import org.kdtree.spec.Builders;
import org.kdtree.treefile.TreeFile;

/**
 * The workbench window: the 2-D build canvas with its builder controls, statistics, tree view,
 * traversal stepper and nearest-neighbour stepper; the builder comparison; the 3-D view; the
 * bouncing balls of the collisions view. {@link #open} shows it.
 */
public final class Workbench extends JFrame {
    /** The scene, settings, tree and selection every view shows. */
    private final WorkbenchModel model = new WorkbenchModel();
    /** The 2-D canvas. */
    private final TreeCanvas canvas = new TreeCanvas(model);
    /** Edits the builder settings. */
    private final BuilderPanel builderPanel = new BuilderPanel(model);
    /** Shows the tree's statistics. */
    private final StatsPanel statsPanel = new StatsPanel(model);
    /** Loads and generates scenes. */
    private final ScenePanel scenePanel = new ScenePanel(model, this::sceneLoaded);
    /** Shows the tree's nodes. */
    private final TreeNodeView treeView = new TreeNodeView(model);
    /** The side panel's tabs. */
    private final JTabbedPane tabs = new JTabbedPane();
    /** Makes the tool buttons exclusive. */
    private final ButtonGroup toolGroup = new ButtonGroup();
    /** The edit tools. */
    private final JToolBar toolBar = new JToolBar("Tools", JToolBar.VERTICAL);
    /** The edit tools, as a menu. */
    private final JMenu toolsMenu = new JMenu("Tools");
    /** The ray traversal stepper. */
    private final StepperPanel stepper;
    /** The k-NN stepper. */
    private final NearestStepperPanel nearest;
    /** The two steppers' tabs. */
    private final JTabbedPane steppers = new JTabbedPane();
    /** The builders side by side. */
    private final CompareView compare;
    /** The 2-D build tab's canvas and side panel. */
    private JSplitPane buildSplit;
    /** The 3-D tab, where File > Open puts JSON scenes and OBJ meshes. */
    private final View3D view3D;
    /** The ball collisions view. */
    private final CollisionsView collisions;
    /** Two scenes' trees compared (the talk's section 5.2). */
    private final CompareDataView compareData;

    /** Builds the window on the built-in talk-figures scene (call on the event thread). */
    public Workbench() {
        this(RECORDER);
    }

    static {
        // The course's worked example is offered by the applications, not listed by the library (see cli.Main).
        Builders.register(new CentreMidpointBuilder().name(), CentreMidpointBuilder::new);
    }

    /** The library's traversal, recorded for the stepper. */
    static final StepperPanel.Recorder RECORDER = TraversalRecorder::record;

    /** Builds the window with a given recorder of traversals (tests may pass their own). */
    Workbench(StepperPanel.Recorder recorder) {
        super("kdtree workbench");
        stepper = new StepperPanel(model, recorder);
        canvas.addOverlay(stepper);
        nearest = new NearestStepperPanel(model);
        canvas.addOverlay(nearest);
        model.addListener(c -> {   // show the stepper of what was just placed
            if (c == WorkbenchModel.Change.RAY && model.ray() != null) steppers.setSelectedComponent(stepper);
            if (c == WorkbenchModel.Change.QUERY && model.query() != null) steppers.setSelectedComponent(nearest);
        });
        setDefaultCloseOperation(DISPOSE_ON_CLOSE);
        scenePanel.selectBuiltin(0);
        tabs.setName("tabs");
        tabs.addTab("2-D build", buildTab());
        tabs.setMnemonicAt(0, KeyEvent.VK_B);
        tabs.setToolTipTextAt(0, "Watch a 2-D build and step through a traversal (Alt+B)");
        compare = new CompareView(model, recorder);
        tabs.addTab("Compare builders", compare);
        tabs.setMnemonicAt(1, KeyEvent.VK_C);
        tabs.setToolTipTextAt(1, "Three builders side by side on the same scene, a kd-tree's or the bounding volume hierarchy's, with the ray's cost in each (Alt+C)");
        view3D = new View3D(model, Path.of("scenes"));
        tabs.addTab("3-D", view3D);
        tabs.setMnemonicAt(2, KeyEvent.VK_3);
        tabs.setToolTipTextAt(2, "Render a 3-D scene (the bundled ones, or any opened) and see its tree (Alt+3)");
        collisions = new CollisionsView(model);
        tabs.addTab("Collisions", collisions);
        tabs.setMnemonicAt(3, KeyEvent.VK_L);
        tabs.setToolTipTextAt(3, "Balls bouncing off the 2-D scene under gravity, with the tree's tests against brute force's (Alt+L)");
        compareData = new CompareDataView(model);
        tabs.addTab("Compare data", compareData);
        tabs.setMnemonicAt(4, KeyEvent.VK_A);   // Alt+D is the 3-D view's Build
        tabs.setDisplayedMnemonicIndexAt(4, "Compare data".indexOf("data") + 1);
        tabs.setToolTipTextAt(4, "Two scenes' kd-trees side by side, where their leaf depths differ, and the distance of their signatures (Alt+A)");
        setContentPane(tabs);
        setJMenuBar(menus());
        pack();   // what every panel asks for, then at least 1280 x 860, but never more than the screen holds
        Dimension natural = getSize();
        setPreferredSize(fitted(new Dimension(Math.max(1280, natural.width), Math.max(860, natural.height)),
                java.awt.GraphicsEnvironment.getLocalGraphicsEnvironment().getMaximumWindowBounds()));
        pack();
        // the side panel its full width, the canvas the rest (on a narrow screen the canvas, not the controls, gives way)
        int side = buildSplit.getRightComponent().getPreferredSize().width;
        buildSplit.setDividerLocation(Math.max(240, buildSplit.getWidth() - buildSplit.getDividerSize() - side));
        setLocationRelativeTo(null);
    }

    /**
     * Opens the workbench on the event thread and returns at once.
     *
     * @param settings the builder and settings it starts with
     */
    public static void open(BuilderSpec settings) {
        SwingUtilities.invokeLater(() -> {
            Workbench w = new Workbench();
            w.model().setSettings(settings);
            w.setVisible(true);
        });
    }

    /** {@return the scene, settings, tree and selection every view shows} */
    public WorkbenchModel model() { return model; }
    /** {@return the 2-D canvas} */
    public TreeCanvas canvas() { return canvas; }
    /** {@return the statistics panel} */
    public StatsPanel stats() { return statsPanel; }
    /** {@return the side panel's tabs} */
    public JTabbedPane tabs() { return tabs; }
    /** {@return the ray traversal stepper} */
    public StepperPanel stepper() { return stepper; }
    /** {@return the k-NN stepper} */
    public NearestStepperPanel nearest() { return nearest; }
    /** {@return the builders side by side} */
    public CompareView compare() { return compare; }

    /** {@return the 3-D tab} */
    public View3D view3D() { return view3D; }
    /** {@return the ball collisions view} */
    public CollisionsView collisions() { return collisions; }
    /** {@return the compare data view} */
    CompareDataView compareData() { return compareData; }
    /** {@return the scene panel} */
    public ScenePanel scenes() { return scenePanel; }

    /**
     * {@return the window's size: {@code wanted}, but no larger than the screen's usable area}
     * (a 1024 x 768 or 1366 x 768 screen gets the whole screen; the side panel scrolls where it must)
     *
     * @param wanted the size the workbench is laid out for
     * @param usable the screen's area for windows (without task bars)
     */
    static Dimension fitted(Dimension wanted, java.awt.Rectangle usable) {
        return new Dimension(Math.min(wanted.width, usable.width), Math.min(wanted.height, usable.height));
    }

    /**
     * The side panel in a vertical scroll pane: its controls keep their sizes on a short screen
     * and scroll, and on a tall one it fills the height (the tree view takes what is left).
     */
    static JScrollPane scrolling(JComponent side) {
        JPanel fill = new ViewportFiller(side);
        JScrollPane scroll = new JScrollPane(fill, JScrollPane.VERTICAL_SCROLLBAR_AS_NEEDED, JScrollPane.HORIZONTAL_SCROLLBAR_NEVER) {
            @Override public Dimension getPreferredSize() {   // room for the scroll bar, so that it never hides a control
                Dimension d = super.getPreferredSize();
                return new Dimension(fill.getPreferredSize().width + getVerticalScrollBar().getPreferredSize().width
                        + getInsets().left + getInsets().right, d.height);
            }
        };
        scroll.setName("side.scroll");
        scroll.setBorder(BorderFactory.createEmptyBorder());
        scroll.getVerticalScrollBar().setUnitIncrement(16);
        return scroll;
    }

    /** A panel as wide as its viewport, and as tall as the viewport when that is taller than the panel needs. */
    private static final class ViewportFiller extends JPanel implements javax.swing.Scrollable {
        ViewportFiller(JComponent content) {
            super(new BorderLayout());
            add(content, BorderLayout.CENTER);
        }

        @Override public Dimension getPreferredScrollableViewportSize() { return getPreferredSize(); }
        @Override public int getScrollableUnitIncrement(java.awt.Rectangle r, int o, int d) { return 16; }
        @Override public int getScrollableBlockIncrement(java.awt.Rectangle r, int o, int d) { return Math.max(16, r.height - 32); }
        @Override public boolean getScrollableTracksViewportWidth() { return true; }
        @Override public boolean getScrollableTracksViewportHeight() {
            return getParent() instanceof javax.swing.JViewport v && v.getHeight() > getPreferredSize().height;
        }
    }

    private JComponent buildTab() {
        JPanel controls = new JPanel();
        controls.setLayout(new BoxLayout(controls, BoxLayout.Y_AXIS));
        controls.add(scenePanel);
        controls.add(builderPanel);
        controls.add(statsPanel);
        treeView.setBorder(BorderFactory.createTitledBorder("Tree"));
        treeView.setPreferredSize(new Dimension(320, 160));   // the least it gets; a tall window gives it the rest
        JPanel side = new JPanel(new BorderLayout());
        side.add(controls, BorderLayout.NORTH);
        side.add(treeView, BorderLayout.CENTER);
        for (EditTool t : EditTool.values()) addTool(t, KeyStroke.getKeyStroke(KeyEvent.VK_F2 + t.ordinal(), 0));
        JPanel centre = new JPanel(new BorderLayout());
        centre.add(toolBar, BorderLayout.WEST);
        centre.add(canvas, BorderLayout.CENTER);
        JScrollPane sideScroll = scrolling(side);
        JSplitPane split = new JSplitPane(JSplitPane.HORIZONTAL_SPLIT, centre, sideScroll);
        split.setResizeWeight(1);
        buildSplit = split;
        JPanel tab = new JPanel(new BorderLayout());
        tab.add(split, BorderLayout.CENTER);
        steppers.setName("steppers");
        steppers.addChangeListener(e -> canvas.repaint());   // only the shown stepper draws over the tree
        steppers.addTab("Ray traversal", stepper);
        steppers.setMnemonicAt(0, KeyEvent.VK_Y);
        steppers.setToolTipTextAt(0, "Step through the cast ray's traversal (a kd-tree's: Algorithm 2; a hierarchy's: nearer box first);"
                + " casting a ray shows it (Alt+Y)");
        steppers.addTab("Nearest neighbours", nearest);
        steppers.setMnemonicAt(1, KeyEvent.VK_E);
        steppers.setToolTipTextAt(1, "Step through the k-NN search around the query point; placing a query shows it (Alt+E)");
        tab.add(steppers, BorderLayout.SOUTH);   // its full height always; on a narrow screen a long line ends in "..."
        return tab;
    }

    private void addTool(EditTool t, KeyStroke key) {
        Action a = action(t.label(), key, t.help() + " (" + KeyEvent.getKeyText(key.getKeyCode()) + ")", () -> {
            canvas.setTool(t);
            for (java.util.Enumeration<javax.swing.AbstractButton> e = toolGroup.getElements(); e.hasMoreElements(); ) {
                javax.swing.AbstractButton b = e.nextElement();
                b.setSelected(b.getName().equals("tool." + t.name()));
            }
        });
        JToggleButton b = new JToggleButton(a);
        b.setName("tool." + t.name());
        b.setSelected(t == EditTool.SELECT);
        b.setFocusable(false);
        b.setMaximumSize(new Dimension(Integer.MAX_VALUE, b.getPreferredSize().height)); // all as wide as the bar
        toolGroup.add(b);
        toolBar.add(b);
        toolsMenu.add(a);
    }

    private JMenuBar menus() {
        JMenuBar bar = new JMenuBar();
        JMenu file = new JMenu("File");
        file.setMnemonic('F');
        file.add(action("Open scene...", ctrl(KeyEvent.VK_O), "Open a 2-D scene (.scene2d), or a JSON scene or OBJ mesh for the 3-D tab", this::openScene));
        file.add(action("Save scene...", ctrl(KeyEvent.VK_S), "Save the scene as a .scene2d file", this::saveScene));
        file.add(action("Export canvas as PNG...", ctrl(KeyEvent.VK_E), "Save the canvas as a PNG image", this::exportPng));
        file.add(action("Save tree...", ctrlShift(KeyEvent.VK_S), "Save the tree of the scene shown, to open it again instead of building it",
                this::saveTree));
        file.add(action("Open tree...", ctrlShift(KeyEvent.VK_O), "Show a tree saved earlier over the scene shown, instead of building one",
                this::openTree));
        file.addSeparator();
        file.add(action("Quit", ctrl(KeyEvent.VK_Q), "Close the workbench", this::dispose));
        bar.add(file);

        JMenu scene = new JMenu("Scene");
        scene.setMnemonic('S');
        int i = 0;
        for (String name : BuiltinScenes.all().keySet()) {
            int index = i++;
            scene.add(action(name, ctrl(KeyEvent.VK_1 + index), "Load the built-in scene '" + name + "'",
                    () -> scenePanel.selectBuiltin(index)));
        }
        scene.addSeparator();
        scene.add(action("Generate random scene", ctrl(KeyEvent.VK_G), "Replace the scene by a random one", scenePanel::generate));
        scene.add(action("Delete selected object", KeyStroke.getKeyStroke(KeyEvent.VK_DELETE, 0), "Remove the selected object",
                () -> { if (model.selectedShape() >= 0) model.removeShape(model.selectedShape()); }));
        bar.add(scene);

        JMenu builders = new JMenu("Builder");
        builders.setMnemonic('U');
        i = 0;
        for (String name : BuilderSpec.names()) {
            int index = i++;
            builders.add(action(name, KeyStroke.getKeyStroke(KeyEvent.VK_1 + index, InputEvent.ALT_DOWN_MASK),
                    "Build with " + name, () -> builderPanel.selectBuilder(index)));
        }
        bar.add(builders);

        toolsMenu.setMnemonic('T');
        bar.add(toolsMenu);

        bar.add(stepperMenu(new StepperWords("Traversal", 'R', "Go to the first step", "Go to the result",
                "Play the traversal step by step", "Clear ray", "Remove the cast ray"), Workbench::ctrl, stepper.controls(), model::clearRay));
        bar.add(stepperMenu(new StepperWords("Nearest", 'N', "Go to the first step of the k-NN search", "Go to the k nearest objects",
                "Play the search step by step", "Clear query", "Remove the query point"), Workbench::ctrlShift, nearest.controls(),
                model::clearQuery));

        JMenu balls = new JMenu("Collisions");
        balls.setMnemonic('O');
        balls.add(action("Start / stop balls", ctrlShift(KeyEvent.VK_B), "Show the collisions view and start or stop its balls",
                () -> { tabs.setSelectedComponent(collisions); collisions.toggle(); }));
        balls.add(action("One frame", ctrlShift(KeyEvent.VK_F), "Show the collisions view and simulate one frame",
                () -> { tabs.setSelectedComponent(collisions); collisions.stepOnce(); }));
        balls.add(action("Drop the balls again", ctrlShift(KeyEvent.VK_R), "Show the collisions view and reset its balls",
                () -> { tabs.setSelectedComponent(collisions); collisions.reset(); }));
        bar.add(balls);

        JMenu view = new JMenu("View");
        view.setMnemonic('V');
        view.add(action("Fit scene", ctrl(KeyEvent.VK_0), "Fit the whole scene in the canvas", canvas::fit));
        view.add(action("Zoom in", ctrl(KeyEvent.VK_EQUALS), "Zoom in (or the mouse wheel)", () -> canvas.zoom(1.25)));
        view.add(action("Zoom out", ctrl(KeyEvent.VK_MINUS), "Zoom out (or the mouse wheel)", () -> canvas.zoom(0.8)));
        bar.add(view);
        return bar;
    }

    /** An action with a name, a shortcut and a tooltip that names the shortcut. */
    static Action action(String name, KeyStroke key, String tip, Runnable r) {
        AbstractAction a = new AbstractAction(name) {
            @Override public void actionPerformed(ActionEvent e) { r.run(); }
        };
        a.putValue(Action.ACCELERATOR_KEY, key);
        a.putValue(Action.SHORT_DESCRIPTION, tip);
        return a;
    }

    /** The words of a stepper's menu: the traversal's and the k-NN search's differ only in these and their keys. */
    private record StepperWords(String title, char mnemonic, String firstTip, String lastTip, String playTip,
            String clearName, String clearTip) {
    }

    /** A stepper's menu: first, back, forward, last, play / pause, and clearing what it steps through. */
    private JMenu stepperMenu(StepperWords w, java.util.function.IntFunction<KeyStroke> key, StepControls steps, Runnable clear) {
        JMenu menu = new JMenu(w.title());
        menu.setMnemonic(w.mnemonic());
        menu.add(action("First step", key.apply(KeyEvent.VK_HOME), w.firstTip(), steps::first));
        menu.add(action("Step back", key.apply(KeyEvent.VK_LEFT), "Go one step back", steps::back));
        menu.add(action("Step forward", key.apply(KeyEvent.VK_RIGHT), "Go one step forward", steps::forward));
        menu.add(action("Last step", key.apply(KeyEvent.VK_END), w.lastTip(), steps::last));
        menu.add(action("Play / pause", key.apply(KeyEvent.VK_P), w.playTip(), steps::togglePlay));
        menu.add(action(w.clearName(), key.apply(KeyEvent.VK_K), w.clearTip(), clear));
        return menu;
    }

    static KeyStroke ctrl(int key) {
        return KeyStroke.getKeyStroke(key, InputEvent.CTRL_DOWN_MASK);
    }

    static KeyStroke ctrlShift(int key) {
        return KeyStroke.getKeyStroke(key, InputEvent.CTRL_DOWN_MASK | InputEvent.SHIFT_DOWN_MASK);
    }

    private void sceneLoaded() {
        canvas.fit();
    }

    private JFileChooser chooser(String ext, String what) {
        JFileChooser c = new JFileChooser(Path.of("scenes").toAbsolutePath().toFile());
        c.setFileFilter(new FileNameExtensionFilter(what, ext));
        return c;
    }

    private void openScene() {
        JFileChooser c = chooser(FileKind.SCENE2D.bareExtension(), "2-D scenes (" + FileKind.SCENE2D.extension() + ")");
        c.addChoosableFileFilter(new FileNameExtensionFilter("3-D scenes (" + FileKind.JSON.extension() + ", " + FileKind.OBJ.extension() + ")",
                FileKind.JSON.bareExtension(), FileKind.OBJ.bareExtension()));
        c.addChoosableFileFilter(new FileNameExtensionFilter("All scenes (.scene2d, .json, .obj)",
                java.util.Arrays.stream(FileKind.values()).map(FileKind::bareExtension).toArray(String[]::new)));
        if (c.showOpenDialog(this) != JFileChooser.APPROVE_OPTION) return;
        try {
            open(c.getSelectedFile().toPath());
        } catch (IOException | RuntimeException e) {
            error("Cannot open the scene", e);
        }
    }

    /**
     * Opens a scene as File &gt; Open does: a .scene2d file in the 2-D views, a JSON scene or OBJ
     * mesh in the 3-D tab (chosen there, ready to render).
     *
     * @param file the scene file
     * @throws IOException if a 2-D scene cannot be read
     */
    public void open(Path file) throws IOException {
        if (View3D.is3D(file.getFileName().toString())) {
            view3D.open(file);
            tabs.setSelectedComponent(view3D);
        } else {
            model.load(file);
            canvas.fit();
        }
    }

    private void saveScene() {
        JFileChooser c = chooser(FileKind.SCENE2D.bareExtension(), "2-D scenes (" + FileKind.SCENE2D.extension() + ")");
        if (c.showSaveDialog(this) != JFileChooser.APPROVE_OPTION) return;
        Path p = withExtension(c.getSelectedFile().toPath(), FileKind.SCENE2D.extension());
        try {
            model.save(p);
        } catch (IOException e) {
            error("Cannot save the scene", e);
        }
    }

    private void saveTree() {
        JFileChooser c = chooser(TreeFile.EXTENSION.substring(1), "Saved trees (" + TreeFile.EXTENSION + ")");
        if (c.showSaveDialog(this) != JFileChooser.APPROVE_OPTION) return;
        try {
            model.saveTree(withExtension(c.getSelectedFile().toPath(), TreeFile.EXTENSION));
        } catch (IOException | RuntimeException e) {
            error("Cannot save the tree", e);
        }
    }

    private void openTree() {
        JFileChooser c = chooser(TreeFile.EXTENSION.substring(1), "Saved trees (" + TreeFile.EXTENSION + ")");
        if (c.showOpenDialog(this) != JFileChooser.APPROVE_OPTION) return;
        try {
            model.loadTree(c.getSelectedFile().toPath());
        } catch (IOException | RuntimeException e) {
            error("Cannot open the tree", e);
        }
    }

    private void exportPng() {
        JFileChooser c = chooser("png", "PNG images");
        if (c.showSaveDialog(this) != JFileChooser.APPROVE_OPTION) return;
        try {
            PngExport.write(canvas.snapshot(), withExtension(c.getSelectedFile().toPath(), ".png"));
        } catch (IOException e) {
            error("Cannot export the image", e);
        }
    }

    private static Path withExtension(Path p, String ext) {
        return p.getFileName().toString().endsWith(ext) ? p : p.resolveSibling(p.getFileName() + ext);
    }

    private void error(String what, Exception e) {
        JOptionPane.showMessageDialog(this, what + ":\n" + e.getMessage(), "kdtree", JOptionPane.ERROR_MESSAGE);
    }
}
