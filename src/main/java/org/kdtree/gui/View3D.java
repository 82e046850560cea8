package org.kdtree.gui;

import java.awt.BorderLayout;
import java.awt.FlowLayout;
import java.awt.Font;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.stream.Stream;
import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JComboBox;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JTextArea;
import javax.swing.SwingWorker;
import org.kdtree.build.Builders;
import org.kdtree.build.KdTreeBuilder;
import org.kdtree.io.SceneLoader;
import org.kdtree.shape.Primitives;
import org.kdtree.tree.KdTree;

/**
 * The 3-D view: pick a scene from scenes/ and a builder, build its tree in the background and
 * show the tree's statistics.
 */
public final class View3D extends JPanel {
    private final JComboBox<String> scene = new JComboBox<>();
    private final JComboBox<String> builder = new JComboBox<>(Builders.names().toArray(String[]::new));
    private final JButton build = new JButton("Build");
    private final JTextArea output = new JTextArea(20, 60);
    private final JLabel status = new JLabel(" ");
    private final Path dir;
    private final WorkbenchModel model;

    public View3D(WorkbenchModel model, Path scenesDir) {
        super(new BorderLayout());
        this.model = model;
        this.dir = scenesDir;
        scene.setName("view3d.scene");
        scene.setToolTipText("A 3-D scene from " + scenesDir);
        builder.setName("view3d.builder");
        builder.setToolTipText("The builder (with the Kt, Ki, lambda, Kmintri, Kmaxdepth of the 2-D view)");
        build.setName("view3d.build");
        build.setToolTipText("Build the scene's tree in the background (Alt+D)");
        build.setMnemonic('D');
        output.setEditable(false);
        output.setName("view3d.output");
        output.setFont(new Font(Font.MONOSPACED, Font.PLAIN, 13));
        output.setToolTipText("The 3-D tree's statistics");
        status.setName("view3d.status");
        JPanel top = new JPanel(new FlowLayout(FlowLayout.LEFT));
        top.add(new JLabel("Scene"));
        top.add(scene);
        top.add(new JLabel("Builder"));
        top.add(builder);
        top.add(build);
        top.add(status);
        add(top, BorderLayout.NORTH);
        JScrollPane sp = new JScrollPane(output);
        sp.setBorder(BorderFactory.createTitledBorder("3-D tree"));
        add(sp, BorderLayout.CENTER);
        for (String s : sceneFiles(scenesDir)) scene.addItem(s);
        if (scene.getItemCount() == 0) status.setText("no 3-D scene in " + scenesDir.toAbsolutePath());
        build.addActionListener(e -> build());
    }

    /** The .obj files of {@code dir}, by name. */
    static List<String> sceneFiles(Path dir) {
        if (!Files.isDirectory(dir)) return List.of();
        try (Stream<Path> s = Files.list(dir)) {
            return s.map(p -> p.getFileName().toString()).filter(n -> n.toLowerCase(Locale.ROOT).endsWith(".obj")).sorted().toList();
        } catch (IOException e) {
            return List.of();
        }
    }

    /** Builds the chosen scene's tree in a background thread and shows its statistics. */
    public void build() {
        String name = (String) scene.getSelectedItem();
        if (name == null) return;
        Path file = dir.resolve(name);
        KdTreeBuilder b = model.settings().withBuilder((String) builder.getSelectedItem()).create();
        build.setEnabled(false);
        status.setText("building " + name + " ...");
        new SwingWorker<String, Void>() {
            @Override protected String doInBackground() throws Exception {
                Primitives p = SceneLoader.load(file);
                long t0 = System.nanoTime();
                KdTree tree = b.build(p);
                double ms = (System.nanoTime() - t0) / 1e6;
                return String.format(Locale.ROOT, "scene: %s (%d primitives)%nbuilder: %s (%s)%nbuild time: %.1f ms%n%s%n",
                        name, p.size(), b.name(), b.describeSettings(), ms, tree.stats().describe());
            }

            @Override protected void done() {
                build.setEnabled(true);
                try {
                    output.setText(get());
                    status.setText("built " + name);
                } catch (Exception e) {
                    Throwable c = e.getCause() != null ? e.getCause() : e;
                    output.setText("cannot build " + name + ": " + c.getMessage());
                    status.setText("failed");
                }
            }
        }.execute();
    }
}
