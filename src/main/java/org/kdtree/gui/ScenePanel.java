package org.kdtree.gui;

import java.awt.FlowLayout;
import java.awt.GridLayout;
import java.util.List;
import java.util.Map;
import java.util.function.IntFunction;
import java.util.function.Supplier;
import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JComboBox;
import javax.swing.JPanel;
import javax.swing.JSpinner;
import org.kdtree.limits.Limits;
import org.kdtree.shape.Shape2D;

/** Picks a built-in scene, or generates a random one with a given count. */
final class ScenePanel extends JPanel {
    /** The built-in scenes by name. */
    private final Map<String, Supplier<List<Shape2D>>> builtins = BuiltinScenes.all();
    /** The random generators by name. */
    private final Map<String, IntFunction<List<Shape2D>>> generators = BuiltinScenes.generators();
    /** Chooses a built-in scene. */
    private final JComboBox<String> scene = new JComboBox<>(builtins.keySet().toArray(String[]::new));
    /** Chooses a random generator. */
    private final JComboBox<String> generator = new JComboBox<>(generators.keySet().toArray(String[]::new));
    /** Generates a random scene. */
    private final JButton generate = new JButton("Generate");
    /** How many objects the generator makes. */
    private final JSpinner count = LimitedSpinner.of(Limits.SCENE_OBJECTS, "objects", 500, 100,
            why -> generate.setEnabled(why == null));
    /** Runs after a new scene replaced the old one. */
    private final Runnable onLoaded;
    /** True while the panel names the loaded scene in its list, so that the list's listener does not load it again. */
    private boolean naming;
    /** The model whose scene this panel replaces. */
    private final WorkbenchModel model;

    /**
     * {@code onLoaded} runs after a new scene replaced the old one (the workbench refits the view).
     *
     * @param model the workbench's model
     * @param onLoaded runs after a new scene replaced the old one
     */
    public ScenePanel(WorkbenchModel model, Runnable onLoaded) {
        super(new GridLayout(0, 1, 2, 2));
        this.model = model;
        this.onLoaded = onLoaded;
        setBorder(BorderFactory.createTitledBorder("Scene"));
        scene.setName("scene");
        scene.setToolTipText("Built-in scenes (Ctrl+1 .. Ctrl+5)");
        generator.setName("generator");
        generator.setToolTipText("Random scene generator");
        count.setName("count");
        count.setToolTipText("Number of objects the generator makes; " + LimitedSpinner.allowed(Limits.SCENE_OBJECTS));
        ((JSpinner.DefaultEditor) count.getEditor()).getTextField().setToolTipText(count.getToolTipText());
        generate.setName("generate");
        generate.setToolTipText("Replace the scene by a random one (Ctrl+G)");
        generate.setMnemonic('G');
        add(scene);
        JPanel row = new JPanel(new FlowLayout(FlowLayout.LEFT, 2, 0));
        row.add(generator);
        row.add(count);
        row.add(generate);
        add(row);
        scene.addActionListener(e -> {
            String name = (String) scene.getSelectedItem();
            if (!naming && builtins.containsKey(name)) loadBuiltin(name);
        });
        generate.addActionListener(e -> generate());
        model.addListener(c -> {
            if (c == WorkbenchModel.Change.TREE || c == WorkbenchModel.Change.BUILDING) showName(model.sceneName());
        });
        showName(model.sceneName());
    }

    /**
     * Shows the scene's name in the box: a built-in one is selected, any other (generated, opened
     * from a file) is shown as an extra last entry, so the box never names a scene that is gone.
     */
    private void showName(String name) {
        naming = true;
        try {
            if (scene.getItemCount() > builtins.size()) scene.removeItemAt(builtins.size());
            if (!builtins.containsKey(name) && !name.isEmpty()) scene.addItem(name);
            scene.setSelectedItem(name);
        } finally {
            naming = false;
        }
    }

    /**
     * Loads built-in scene number {@code index} (0-based).
     *
     * @param index the scene's position in the list
     */
    public void selectBuiltin(int index) {
        if (index < scene.getItemCount()) {
            if (scene.getSelectedIndex() == index) loadBuiltin((String) scene.getSelectedItem());
            else scene.setSelectedIndex(index);
        }
    }

    /**
     * Loads the built-in scene of that name.
     *
     * @param name a name from {@link BuiltinScenes#all()}
     */
    public void loadBuiltin(String name) {
        model.setScene(name, builtins.get(name).get());
        onLoaded.run();
    }

    /** Replaces the scene by the chosen generator's output for the chosen count. */
    public void generate() {
        String g = (String) generator.getSelectedItem();
        int n = ((Number) count.getValue()).intValue();
        model.setScene(g + " (" + n + ")", generators.get(g).apply(n));
        onLoaded.run();
    }
}
