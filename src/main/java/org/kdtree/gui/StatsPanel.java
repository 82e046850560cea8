package org.kdtree.gui;

import java.awt.GridLayout;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import javax.swing.BorderFactory;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JProgressBar;
import org.kdtree.accel.TreeStats;

/**
 * The statistics of the current tree or bounding volume hierarchy: build time, nodes, leaves,
 * empty leaves, depth, refs per leaf, SAH cost (the same Kt and Ki for both) and memory.
 */
final class StatsPanel extends JPanel {
    /** The value label of each statistic, by name. */
    private final Map<String, JLabel> values = new LinkedHashMap<>();
    /** Shown while a background build runs. */
    private final JProgressBar progress = new JProgressBar();

    /**
     * A panel showing the statistics of the tree of {@code model}.
     *
     * @param model the workbench's model
     */
    public StatsPanel(WorkbenchModel model) {
        super(new GridLayout(0, 2, 8, 1));
        setBorder(BorderFactory.createTitledBorder("Statistics"));
        add("objects", "Objects in the scene");
        add("build time", "Wall-clock time of the last build (includes JIT warm-up at first)");
        add("nodes", "Interior nodes plus leaves");
        add("leaves", "Leaves");
        add("empty leaves", "Leaves with no object: the shaded voxels");
        add("depth", "Depth of the deepest leaf (the root has depth 0)");
        add("refs / leaf", "Object references per non-empty leaf");
        add("SAH cost", "Expected cost of a random ray: Kt per node visited plus Ki per object tested");
        add("memory", "Bytes the structure's arrays hold (a hierarchy's: both its layouts)");
        progress.setIndeterminate(true);
        progress.setName("stat.building");
        progress.setToolTipText("A large scene is built in the background; the views show the last tree until it is ready");
        progress.setVisible(false);
        add(new JLabel());
        add(progress);
        model.addListener(c -> {
            if (c == WorkbenchModel.Change.TREE) show(model);
            if (c == WorkbenchModel.Change.BUILDING) set("build time", "building ...");
            if (c == WorkbenchModel.Change.FAULT) set("build time", "failed (stale tree)");
            progress.setVisible(model.building());
        });
        show(model);
    }

    private void add(String name, String tip) {
        JLabel k = new JLabel(name + ":"), v = new JLabel("-");
        k.setToolTipText(tip);
        v.setToolTipText(tip);
        v.setName("stat." + name);
        values.put(name, v);
        add(k);
        add(v);
    }

    /**
     * {@return the text shown for statistic {@code name}} (for tests).
     *
     * @param name the statistic's name
     */
    public String value(String name) {
        return values.get(name).getText();
    }

    private void show(WorkbenchModel m) {
        TreeStats s = m.built().stats();
        set("objects", Integer.toString(m.scene().size()));
        set("build time", String.format(Locale.ROOT, "%.2f ms", m.buildMillis())
                + (m.loadedFrom() != null ? " (a load of " + m.loadedFrom().getFileName() + ")" : ""));
        set("nodes", Integer.toString(s.nodes()));
        set("leaves", Integer.toString(s.leaves()));
        set("empty leaves", Integer.toString(s.emptyLeaves()));
        set("depth", Integer.toString(s.maxDepth()));
        set("refs / leaf", String.format(Locale.ROOT, "%.2f", s.averageRefsPerLeaf()));
        set("SAH cost", String.format(Locale.ROOT, "%.2f", s.expectedCost()));
        set("memory", memory(s.memoryBytes()));
    }

    /** {@return bytes as people read them: "840 B", "12.3 KB", "4.50 MB"} */
    static String memory(long bytes) {
        if (bytes < 1024) return bytes + " B";
        if (bytes < 1024 * 1024) return String.format(Locale.ROOT, "%.1f KB", bytes / 1024.0);
        return String.format(Locale.ROOT, "%.2f MB", bytes / (1024.0 * 1024));
    }

    private void set(String name, String text) {
        values.get(name).setText(text);
    }
}
