package org.kdtree.gui;

import java.awt.GridBagConstraints;
import java.awt.GridBagLayout;
import java.awt.Insets;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Set;
import javax.swing.BorderFactory;
import javax.swing.JComboBox;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JSlider;
import org.kdtree.accel.Setting;
import org.kdtree.accel.SharedSettings;
import org.kdtree.kdtree.SahBuilder;
import org.kdtree.kdtree.SahSettings;
import org.kdtree.spec.BuilderSpec;

/**
 * The builder controls, an editor of the model's {@link BuilderSpec}: which builder, then one
 * control per row of {@link Setting} (made by {@link SettingControl}), with lambda also as a
 * slider and the automatic depth cap spelled out. Every change rebuilds the tree at once.
 * The builders are the kd-tree builders and the bounding volume hierarchy's ({@code bvh}).
 * Controls whose setting does not apply to the chosen builder are greyed out and left out of the
 * spec (which would refuse them); each spinner takes its row's range, states it in its tooltip and,
 * for a typed value outside it, says so below instead of reverting silently.
 */
final class BuilderPanel extends JPanel {
    /**
     * The settings the workbench does not offer: a preset (the controls set what it would, and
     * would override it) and threads (its scenes build in milliseconds on one; the tree is the same).
     */
    private static final Set<Setting<?>> NOT_OFFERED = Set.of(SahSettings.QUALITY, SharedSettings.THREADS);
    /** The settings only the binned plane search uses: greyed out, and not given, under the exact ones (a hierarchy always bins). */
    private static final Set<Setting<?>> BINNED_ONLY = Set.of(SharedSettings.BINS, SahSettings.EXACT_BELOW);

    /** The model whose builder settings this panel edits. */
    private final WorkbenchModel model;
    /** The builder's name. */
    private final JComboBox<String> builder = new JComboBox<>(BuilderSpec.names().toArray(String[]::new));
    /** Why a typed value is refused, or blank. */
    private final JLabel rejection = new JLabel(" ");
    /** The last build's fault, in the builder's own line (the tree shown is then stale), or blank. */
    private final JLabel fault = new JLabel(" ");
    /** One control per setting offered, in the table's order. */
    private final Map<Setting<?>, SettingControl> controls = new LinkedHashMap<>();
    private final Map<Setting<?>, JLabel> labels = new LinkedHashMap<>();
    /** lambda as a slider, in hundredths. */
    private final JSlider lambdaSlider = new JSlider((int) Math.round(SahSettings.LAMBDA.limit().min() * 100),
            (int) Math.round(SahSettings.LAMBDA.limit().max() * 100), (int) Math.round(SahSettings.LAMBDA.defaultValue() * 100));
    /** The automatic depth cap the current scene gets. */
    private final JLabel autoDepth = new JLabel();
    /** True while the panel sets its own controls, so that their listeners do not write back. */
    private boolean updating;

    /**
     * A panel editing the builder settings of {@code model}.
     *
     * @param model the workbench's model
     */
    public BuilderPanel(WorkbenchModel model) {
        super(new GridBagLayout());
        this.model = model;
        setBorder(BorderFactory.createTitledBorder("Builder"));
        name(builder, "builder", "Builder (Alt+1, Alt+2, ...): median-plane splits the voxel in the middle, object-median at the median object; "
                + "sah minimises the expected cost; bvh builds a bounding volume hierarchy by the same cost; others are registered builders");
        name(lambdaSlider, "lambdaSlider", "lambda as a slider, in hundredths");
        autoDepth.setName("autoDepth");
        rejection.setName("rejection");
        rejection.setForeground(new java.awt.Color(170, 0, 0));
        int y = 0;
        row(y++, "Builder", builder);
        for (Setting<?> s : BuilderSpec.allSettingRows()) {
            if (NOT_OFFERED.contains(s)) continue;
            // the plane search's O(N^2) naive algorithm is too slow to be live
            SettingControl c = SettingControl.of(s, this::reject, v -> v != SahBuilder.Algorithm.NAIVE);
            controls.put(s, c);
            labels.put(s, row(y++, c.label(), c.component()));
            if (s == SahSettings.LAMBDA) row(y++, "", lambdaSlider);
            if (s == SharedSettings.MAX_DEPTH) row(y++, "", autoDepth);
            c.onChange(this::apply);
        }
        row(y++, "", rejection);
        fault.setName("builder.fault");
        fault.setForeground(new java.awt.Color(170, 0, 0));
        wideRow(y, fault);
        rejection.setVisible(false);
        fault.setVisible(false);
        builder.addActionListener(e -> apply());
        builder.setRenderer(new javax.swing.DefaultListCellRenderer() {
            @Override public java.awt.Component getListCellRendererComponent(javax.swing.JList<?> list, Object value, int index,
                                                                       boolean selected, boolean focus) {
                String name = value == null ? "" : value.toString();
                return super.getListCellRendererComponent(list, model.hung(name) ? name + " (hung)" : name, index, selected, focus);
            }
        });
        lambdaSlider.addChangeListener(e -> {
            if (!updating) controls.get(SahSettings.LAMBDA).show(lambdaSlider.getValue() / 100.0);
        });
        show(model.settings());
        model.addListener(c -> {
            if (c == WorkbenchModel.Change.TREE) show(model.settings());
            if (c == WorkbenchModel.Change.TREE || c == WorkbenchModel.Change.FAULT) showFault();
        });
    }

    /** Shows the last build's fault, wrapped to the panel's width, with the whole line as its tooltip; blank if it built. */
    private void showFault() {
        var f = model.fault();
        fault.setText(f == null ? " " : "<html><div style='width:230px'>" + escaped(f.getMessage())
                + "<br><b>The tree shown is the previous one (stale).</b></div></html>");
        fault.setToolTipText(f == null ? null : f.getMessage());
        fault.setVisible(f != null);   // no blank row: the tree list below keeps the room
        builder.repaint(); // its box marks a hung builder
    }

    private static String escaped(String s) {
        return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;");
    }

    /** Shows why the value just typed is not taken (null: the text is valid again). */
    private void reject(String why) {
        rejection.setText(why == null ? " " : why);
        rejection.setVisible(why != null);
        rejection.setToolTipText(why);
    }

    /**
     * Selects the builder at {@code index} in the list (keyboard shortcut).
     *
     * @param index 0-based, in {@link BuilderSpec#names()} order
     */
    public void selectBuilder(int index) {
        if (index < builder.getItemCount()) builder.setSelectedIndex(index);
    }

    private void apply() {
        if (updating) return;
        String name = (String) builder.getSelectedItem();
        BuilderSpec s = BuilderSpec.of(name);
        for (SettingControl c : controls.values()) if (live(c.setting(), name)) s = c.giveTo(s);
        show(s);
        model.setSettings(s);
    }

    /** Whether {@code setting} counts for builder {@code name} as the controls are set (bins only under a binned search). */
    private boolean live(Setting<?> setting, String name) {
        return BuilderSpec.applies(setting, name) && (!BINNED_ONLY.contains(setting) || !BuilderSpec.applies(SahSettings.ALGORITHM, name)
                || controls.get(SahSettings.ALGORITHM).value() == SahBuilder.Algorithm.BINNED);
    }

    private void show(BuilderSpec s) {
        updating = true;
        try {
            builder.setSelectedItem(s.builder());
            for (SettingControl c : controls.values()) if (BuilderSpec.applies(c.setting(), s.builder())) c.show(s.value(c.setting()));
            for (SettingControl c : controls.values()) {   // another builder's setting, or bins under an exact search: not shown
                boolean live = live(c.setting(), s.builder());
                c.component().setEnabled(live);
                c.component().setVisible(live);
                labels.get(c.setting()).setVisible(live);
            }
            SettingControl lambda = controls.get(SahSettings.LAMBDA);
            lambdaSlider.setValue((int) Math.round((Double) lambda.value() * 100));
            lambdaSlider.setEnabled(lambda.component().isEnabled());
            lambdaSlider.setVisible(lambda.component().isVisible());
            showAutoDepth(s);
        } finally {
            updating = false;
        }
    }

    /** Spells out the depth cap: fixed, or the automatic one the builder gives the current scene. */
    private void showAutoDepth(BuilderSpec s) {
        int n = model.scene().size();
        int depth = (Integer) controls.get(SharedSettings.MAX_DEPTH).value();
        int auto = s.forBuilder(s.builder()).with(SharedSettings.MAX_DEPTH, null).structureBuilder().depthCap(n);
        autoDepth.setText(depth >= 0 ? "fixed depth cap " + depth : "-1 = auto: depth cap " + auto);
        autoDepth.setToolTipText("the " + s.builder() + " builder's automatic depth cap for these " + n + " objects is " + auto);
    }

    private static void name(JComponent c, String name, String tip) {
        c.setName(name);
        c.setToolTipText(tip);
    }

    /** A row of one component across both columns (a message as wide as the panel). */
    private void wideRow(int y, JComponent c) {
        GridBagConstraints g = new GridBagConstraints();
        g.gridy = y;
        g.gridwidth = 2;
        g.insets = new Insets(2, 4, 2, 4);
        g.anchor = GridBagConstraints.WEST;
        g.fill = GridBagConstraints.HORIZONTAL;
        add(c, g);
    }

    private JLabel row(int y, String label, JComponent c) {
        GridBagConstraints g = new GridBagConstraints();
        g.gridy = y;
        g.insets = new Insets(2, 4, 2, 4);
        g.anchor = GridBagConstraints.WEST;
        JLabel l = new JLabel(label);
        l.setLabelFor(c);
        l.setToolTipText(c.getToolTipText());
        add(l, g);
        g.gridx = 1;
        g.fill = GridBagConstraints.HORIZONTAL;
        g.weightx = 1;
        add(c, g);
        return l;
    }
}
