package org.kdtree.gui;

import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.Font;
import java.awt.Graphics;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;
import java.util.stream.Stream;
import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JComboBox;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JSpinner;
import javax.swing.JSplitPane;
import javax.swing.JTextArea;
import javax.swing.SwingUtilities;
import javax.swing.Timer;
import org.kdtree.io.BundledScenes;
import org.kdtree.io.FileKind;
import org.kdtree.io.PrimitivesReader;
import org.kdtree.kdtree.Supervisor;
import org.kdtree.kdtree.Traverser;
import org.kdtree.limits.Deadlines;
import org.kdtree.render.Image;
import org.kdtree.render.RenderJob;
import org.kdtree.render.Renderer;
import org.kdtree.scene.Scene;
import org.kdtree.shape.Primitives;
import org.kdtree.spec.BuilderSpec;

/**
 * The 3-D view: pick a scene (the bundled ones, those of a scenes folder, or a file opened with
 * File &gt; Open) and a builder. A JSON scene is rendered with the
 * library's ray tracer ({@code render.Tracer} over a ray query per thread), tile by tile, the
 * image shown as it fills in, then the render's statistics (rays by kind, times, the tree). An
 * OBJ mesh, which has no camera, gets its tree built and its statistics shown.
 */
final class View3D extends JPanel {
    /** Chooses the 3-D scene. */
    private final JComboBox<String> scene = new JComboBox<>();
    /** Chooses the builder. */
    private final JComboBox<String> builder = new JComboBox<>(BuilderSpec.names().toArray(String[]::new));
    /** Builds the tree and renders. */
    private final JButton build = new JButton("Render");
    /** What the view is doing, or blank. */
    private final JLabel status = new JLabel(" ");
    /** The image width in pixels. */
    private final JSpinner width = LimitedSpinner.of(WorkbenchLimits.PREVIEW_WIDTH, "Width", 480, 16, this::reject);
    /** Stops a build or render under way. */
    private final JButton stop = new JButton("Stop");
    /** The statistics of the last build or render. */
    private final JTextArea output = new JTextArea(20, 30);
    /** Scales the image to the panel (off: 1:1, with scroll bars). */
    private final javax.swing.JCheckBox fit = new javax.swing.JCheckBox("Fit", true);
    /** Shows the image rendered so far. */
    private final Picture picture = new Picture();
    /** The scenes the box offers, by the name it shows. */
    private final java.util.Map<String, Path> files = new java.util.LinkedHashMap<>();
    /** The model whose builder settings the build uses. */
    private final WorkbenchModel model;
    /** Set by {@link #stop} to cancel the build or render under way. */
    private volatile boolean cancelled;
    /** Runs a plug-in's builds: a builder that throws, hangs or crawls is stopped and named, and Build is free again. */
    private static final Supervisor SUPERVISOR = Supervisor.of(Deadlines.WORKBENCH).trustingTheLibrary();

    /** The thread building or rendering, or null. */
    private Thread running;
    /** Image and statistics side by side; widened for the statistics when a line would be cut. */
    private JSplitPane split;
    /** Whether the view has been shown: the first showing renders the chosen scene unasked. */
    private boolean shownOnce;

    /**
     * A view rendering the bundled 3-D scenes and those of {@code scenesDir}, if it exists.
     *
     * @param model the workbench's model
     * @param scenesDir a folder of JSON scenes and OBJ meshes, if any
     */
    public View3D(WorkbenchModel model, Path scenesDir) {
        super(new BorderLayout());
        this.model = model;
        scene.setName("view3d.scene");
        scene.setToolTipText("A 3-D scene (bundled, from " + scenesDir + ", or opened with File > Open):"
                + " JSON scenes are rendered, OBJ meshes get their tree's statistics");
        builder.setName("view3d.builder");
        builder.setToolTipText("The builder, a kd-tree's or bvh (with the Kt, Ki, lambda, Kmintri, Kmaxdepth of the 2-D view); "
                + "it follows the 2-D view's builder");
        builder.setSelectedItem(model.settings().builder());   // gui -b bvh: the 3-D tab renders with the BVH too
        model.addListener(c -> {   // a new builder, built at once (TREE) or in the background (BUILDING)
            if ((c == WorkbenchModel.Change.TREE || c == WorkbenchModel.Change.BUILDING)
                    && !model.settings().builder().equals(builder.getSelectedItem()))
                builder.setSelectedItem(model.settings().builder());
        });
        width.setName("view3d.width");
        width.setToolTipText("Image width in pixels (the height follows the scene's aspect ratio); "
                + LimitedSpinner.allowed(WorkbenchLimits.PREVIEW_WIDTH));
        ((JSpinner.DefaultEditor) width.getEditor()).getTextField().setToolTipText(width.getToolTipText());
        fit.setName("view3d.fit");
        fit.setToolTipText("Scale the image to the panel (off: 1:1, with scroll bars)");
        fit.addActionListener(e -> picture.fit(fit.isSelected()));
        build.setName("view3d.build");
        build.setToolTipText("Build the tree and render the scene, showing the image as it fills in (Alt+D)");
        build.setMnemonic('D');
        stop.setName("view3d.stop");
        stop.setToolTipText("Stop the render");
        stop.setEnabled(false);
        output.setEditable(false);
        output.setName("view3d.output");
        output.setFont(new Font(Font.MONOSPACED, Font.PLAIN, 12));
        output.setToolTipText("The render's statistics and the tree's");
        status.setName("view3d.status");
        picture.setToolTipText("The rendered image");
        JPanel top = Widgets.row("Scene", scene, "Builder", builder, "Width", width, fit, build, stop, status);
        add(top, BorderLayout.NORTH);
        JScrollPane text = new JScrollPane(output);
        text.setBorder(BorderFactory.createTitledBorder("Statistics"));
        JScrollPane pic = new JScrollPane(picture);
        pic.setBorder(BorderFactory.createTitledBorder("Image"));
        split = new JSplitPane(JSplitPane.HORIZONTAL_SPLIT, pic, text);
        split.setResizeWeight(0.7);   // the image gets most of the room; the statistics are a narrow column
        add(split, BorderLayout.CENTER);
        for (String f : BundledScenes.FILES) if (is3D(f)) offer(f, BundledScenes.path(f));
        for (String s : sceneFiles(scenesDir)) offer(s, scenesDir.resolve(s));
        scene.addActionListener(e -> build.setText(isJson((String) scene.getSelectedItem()) ? "Render" : "Build"));
        build.addActionListener(e -> build());
        stop.addActionListener(e -> cancelled = true);
        addHierarchyListener(e -> renderOnFirstShow());
    }

    /** A tab first opened starts rendering at once, rather than showing a grey, empty image until Render. */
    private void renderOnFirstShow() {
        if (shownOnce || !isShowing()) return;
        shownOnce = true;
        SwingUtilities.invokeLater(this::build);   // after the tab is laid out
    }

    /** The JSON scenes, then the .obj meshes of {@code dir}, by name. */
    static List<String> sceneFiles(Path dir) {
        if (!Files.isDirectory(dir)) return List.of();
        try (Stream<Path> s = Files.list(dir)) {
            List<String> names = s.map(p -> p.getFileName().toString()).sorted().toList();
            List<String> out = new ArrayList<>(names.stream().filter(n -> FileKind.of(n) == FileKind.JSON).toList());
            out.addAll(names.stream().filter(n -> FileKind.of(n) == FileKind.OBJ).toList());
            return out;
        } catch (IOException e) {
            return List.of();
        }
    }

    /** Adds a scene to the box unless one of that name is there already (a bundled scene wins over its copy in scenes/). */
    private void offer(String name, Path file) {
        if (files.putIfAbsent(name, file) == null) scene.addItem(name);
    }

    /**
     * Adds a JSON scene or OBJ mesh to the box (File &gt; Open) and chooses it.
     *
     * @param file the scene file
     * @throws IllegalArgumentException if it is neither JSON nor OBJ
     */
    public void open(Path file) {
        String name = file.getFileName().toString();
        if (!is3D(name)) throw new IllegalArgumentException(file + ": the 3-D view opens JSON scenes and OBJ meshes");
        if (files.containsKey(name) && !files.get(name).equals(file)) name = file.toAbsolutePath().toString();
        files.put(name, file);
        if (((javax.swing.DefaultComboBoxModel<String>) scene.getModel()).getIndexOf(name) < 0) scene.addItem(name);
        scene.setSelectedItem(name);
    }

    /** {@return whether {@code name} is a JSON scene or an OBJ mesh} */
    static boolean is3D(String name) {
        FileKind kind = FileKind.of(name);
        return kind != null && kind.hasTriangles();
    }

    private static boolean isJson(String name) {
        return name != null && FileKind.of(name) == FileKind.JSON;
    }

    /** Renders (JSON) or builds (OBJ) the chosen scene in the background. */
    public void build() {
        String name = (String) scene.getSelectedItem();
        if (name == null || running != null) return;
        Path file = files.get(name);
        BuilderSpec b = model.settings().forBuilder((String) builder.getSelectedItem());
        int w = ((Number) width.getValue()).intValue();
        cancelled = false;
        build.setEnabled(false);
        stop.setEnabled(true);
        status.setText((isJson(name) ? "rendering " : "building ") + name + " ...");
        running = new Thread(() -> {
            String text;
            try {
                text = isJson(name) ? render(file, b, w) : statistics(file, b);
            } catch (IOException | RuntimeException e) {
                text = "cannot " + (isJson(name) ? "render " : "build ") + name + ": " + e.getMessage();
            }
            String result = text;
            SwingUtilities.invokeLater(() -> finished(name, result));
        }, "workbench-3d");
        running.setDaemon(true);
        running.start();
    }

    /** {@return the builder the 3-D view builds with, as its box shows it} */
    String builderChoice() { return (String) builder.getSelectedItem(); }

    /** {@return whether a build or render is under way} */
    public boolean busy() { return running != null; }

    /** A width outside its limit blocks Render and says why; a valid one frees it again. */
    private void reject(String why) {
        if (running != null) return;
        status.setText(why == null ? " " : why);
        build.setEnabled(why == null);
    }

    /**
     * Chooses the scene (a name the box offers, e.g. "cornell-box.json") and the image width.
     *
     * @param sceneName a name the box offers
     * @param imageWidth the image width in pixels
     */
    public void choose(String sceneName, int imageWidth) {
        scene.setSelectedItem(sceneName);
        width.setValue(imageWidth);
    }

    /** {@return the statistics shown after the last build or render} */
    public String statisticsText() { return output.getText(); }

    /** {@return the image rendered so far} (null before any render). */
    public BufferedImage image() { return picture.img; }

    private void finished(String name, String text) {
        running = null;
        output.setText(text);
        output.setCaretPosition(0);
        widenForStatistics();
        status.setText((cancelled ? "stopped " : text.startsWith("cannot ") ? "failed: " : "done: ") + name);
        build.setEnabled(true);
        stop.setEnabled(false);
        picture.repaint();
    }

    /** Moves the divider left so the statistics' longest line shows whole, leaving the image at least a third. */
    private void widenForStatistics() {
        JScrollPane text = (JScrollPane) split.getRightComponent();   // its preferred width is 30 columns, not the text's
        java.awt.Insets in = text.getInsets();
        int need = output.getPreferredSize().width + in.left + in.right + text.getVerticalScrollBar().getPreferredSize().width;
        if (split.getWidth() <= 0 || text.getWidth() >= need) return;
        split.setDividerLocation(Math.max(split.getWidth() / 3, split.getWidth() - split.getDividerSize() - need));
    }

    private String statistics(Path file, BuilderSpec b) throws IOException {
        Primitives p = PrimitivesReader.read(file);
        String settings = b.describe();
        long t0 = System.nanoTime();
        var built = b.build(p, SUPERVISOR);
        double ms = (System.nanoTime() - t0) / 1e6;
        return String.format(Locale.ROOT, "scene: %s (%s, no camera: statistics only)%nbuilder: %s (%s)%n"
                + "build time: %.1f ms%n%s%n", file.getFileName(), RenderJob.count(p.size(), "primitive"), b.builder(), settings, ms,
                built.stats().describe());
    }

    /**
     * Renders with the library's renderer ({@link RenderJob}, as the render command does) over all
     * cores; the picture shows the image as tiles complete, and Stop ends it after the tiles under way.
     */
    private String render(Path file, BuilderSpec b, int w) throws IOException {
        Scene s = PrimitivesReader.readScene(file);
        int h = Math.max(1, (int) Math.round(w * (double) s.camera().height() / s.camera().width()));
        AtomicReference<Image> growing = new AtomicReference<>();
        AtomicInteger done = new AtomicInteger(), total = new AtomicInteger(1);
        Timer refresh = new Timer(150, e -> {
            Image img = growing.get();
            if (img != null) picture.show(img.toBufferedImage(), done.get(), total.get());
        });
        SwingUtilities.invokeLater(refresh::start);
        Renderer.Options options = Renderer.Options.defaults().withStop(() -> cancelled)
                .withProgress((d, t, image) -> {
                    growing.set(image);
                    total.set(t);
                    done.accumulateAndGet(d, Math::max);
                });
        RenderJob job = RenderJob.run(s.withImageSize(w, h), b, SUPERVISOR, options);
        SwingUtilities.invokeLater(() -> {
            refresh.stop();
            picture.show(job.result().image().toBufferedImage(), done.get(), total.get());
        });
        return job.summary();
    }

    /** The image: scaled to fit the panel (keeping its aspect ratio), or at 1:1 with scroll bars. */
    private final class Picture extends JComponent implements javax.swing.Scrollable {
        private BufferedImage img;
        private boolean fit = true;

        void show(BufferedImage i, int done, int total) {
            img = i;
            setPreferredSize(new Dimension(i.getWidth(), i.getHeight()));
            revalidate();
            repaint();
            if (running != null) status.setText(String.format(Locale.ROOT, "rendering: %d / %d tiles", done, total));
        }

        void fit(boolean on) {
            fit = on;
            revalidate();
            repaint();
        }

        @Override protected void paintComponent(Graphics g) {
            if (img == null) return;
            if (!fit) {
                g.drawImage(img, 0, 0, null);
                return;
            }
            double scale = Math.min((double) getWidth() / img.getWidth(), (double) getHeight() / img.getHeight());
            int w = Math.max(1, (int) (img.getWidth() * scale)), h = Math.max(1, (int) (img.getHeight() * scale));
            ((java.awt.Graphics2D) g).setRenderingHint(java.awt.RenderingHints.KEY_INTERPOLATION,
                    java.awt.RenderingHints.VALUE_INTERPOLATION_BILINEAR);
            g.drawImage(img, (getWidth() - w) / 2, (getHeight() - h) / 2, w, h, null);
        }

        @Override public Dimension getPreferredScrollableViewportSize() { return getPreferredSize(); }
        @Override public int getScrollableUnitIncrement(java.awt.Rectangle r, int o, int d) { return 16; }
        @Override public int getScrollableBlockIncrement(java.awt.Rectangle r, int o, int d) { return 128; }
        @Override public boolean getScrollableTracksViewportWidth() { return fit; }    // fitted: never a scroll bar
        @Override public boolean getScrollableTracksViewportHeight() { return fit; }
    }
}
