package org.kdtree.gui;

import java.awt.GridBagConstraints;
import java.awt.GridBagLayout;
import java.awt.Insets;
import javax.swing.BorderFactory;
import javax.swing.JCheckBox;
import javax.swing.JComboBox;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JSlider;
import javax.swing.JSpinner;
import org.kdtree.build.BuilderSpec;
import org.kdtree.build.Builders;
import org.kdtree.build.KdTreeBuilder;
import org.kdtree.build.SahBuilder;
import org.kdtree.build.Setting;
import org.kdtree.build.SlidingMidpointBuilder;
import org.kdtree.limits.Limits;

/**
 * The builder controls, an editor of the model's {@link BuilderSpec}: which builder, Kt, Ki,
 * lambda (spinner and slider), the SAH's plane search and bins, perfect splits, Kmintri, the
 * leaf size and Kmaxdepth. Every change rebuilds the tree at once. Controls whose {@link Setting}
 * does not apply to the chosen builder are greyed out and left out of the spec (which would refuse
 * them); each spinner takes the range of {@link Limits}, states it in its tooltip and, for a typed
 * value outside it, says so below instead of reverting silently.
 */
public final class BuilderPanel extends JPanel {
    /** The model whose builder settings this panel edits. */
    private final WorkbenchModel model;
    /** The builder's name. */
    private final JComboBox<String> builder = new JComboBox<>(Builders.names().toArray(String[]::new));
    /** Why a typed value is refused, or blank. */
    private final JLabel rejection = new JLabel(" ");
    /** The last build's fault, in the builder's own line (the tree shown is then stale), or blank. */
    private final JLabel fault = new JLabel(" ");
    /** Kt, the cost of traversing a node. */
    private final JSpinner kt = LimitedSpinner.of(Limits.KT, "Kt", 15, 1, this::reject);
    /** Ki, the cost of intersecting an object. */
    private final JSpinner ki = LimitedSpinner.of(Limits.KI, "Ki", 20, 1, this::reject);
    /** lambda, the SAH's weight of a plane that leaves one child empty. */
    private final JSpinner lambda = LimitedSpinner.of(Limits.LAMBDA, "lambda", 0.8, 0.05, this::reject);
    /** lambda as a slider, in hundredths. */
    private final JSlider lambdaSlider = new JSlider((int) Math.round(Limits.LAMBDA.min() * 100), 100, 80);
    /** The SAH's plane-search algorithm (NAIVE, O(N^2), is left out: too slow to be live). */
    private final JComboBox<SahBuilder.Algorithm> algorithm = new JComboBox<>(java.util.Arrays.stream(SahBuilder.Algorithm.values())
            .filter(a -> a != SahBuilder.Algorithm.NAIVE).toArray(SahBuilder.Algorithm[]::new)); // O(N^2): too slow to be live
    /** Bins per axis of the binned SAH. */
    private final JSpinner bins = LimitedSpinner.of(Limits.BINS, "bins", SahBuilder.DEFAULT_BINS, 1, this::reject);
    /** Perfect splits (exact clipping) or bounding boxes only. */
    private final JCheckBox perfectSplits = new JCheckBox("perfect splits", true);
    /** The sliding-midpoint builder's largest leaf. */
    private final JSpinner leafSize = LimitedSpinner.of(Limits.LEAF_SIZE, "leaf size", SlidingMidpointBuilder.DEFAULT_LEAF_SIZE, 1, this::reject);
    /** Kmintri, for the axis-cycling builders. */
    private final JSpinner minPrims = LimitedSpinner.of(Limits.MIN_PRIMITIVES, "Kmintri", 2, 1, this::reject);
    /** Kmaxdepth, or -1 for the automatic depth cap. */
    private final JSpinner maxDepth = LimitedSpinner.of(Limits.MAX_DEPTH, "Kmaxdepth", -1, 1, this::reject);
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
        name(builder, "builder", "Builder (Alt+1, Alt+2, ...): median-plane splits the voxel in the middle, object-median at the median object; sah minimises the expected cost; others are registered builders");
        name(kt, "kt", "Kt: cost of traversing one node (SAH); " + LimitedSpinner.allowed(Limits.KT));
        name(ki, "ki", "Ki: cost of intersecting one object (SAH); " + LimitedSpinner.allowed(Limits.KI));
        name(lambda, "lambda", "lambda: weight of a plane that cuts off empty space (1 = no bonus); SAH only; "
                + LimitedSpinner.allowed(Limits.LAMBDA));
        name(lambdaSlider, "lambdaSlider", "lambda as a slider, in hundredths");
        name(algorithm, "algorithm", "How the SAH searches for its planes: the exact searches build the same tree at different speeds (SAH only)");
        name(bins, "bins", "Bins per axis of the binned SAH (SAH with the binned search only); " + LimitedSpinner.allowed(Limits.BINS));
        name(perfectSplits, "perfectSplits", "Clip each straddling object to both children exactly (on) or keep bounding boxes (off)");
        name(leafSize, "leafSize", "Largest leaf of the sliding-midpoint builder; " + LimitedSpinner.allowed(Limits.LEAF_SIZE));
        name(minPrims, "kmintri", "Kmintri: a voxel with at most this many objects becomes a leaf (median builders); "
                + LimitedSpinner.allowed(Limits.MIN_PRIMITIVES));
        name(maxDepth, "kmaxdepth", "Kmaxdepth: maximum depth; " + LimitedSpinner.allowed(Limits.MAX_DEPTH));
        autoDepth.setName("autoDepth");
        rejection.setName("rejection");
        rejection.setForeground(new java.awt.Color(170, 0, 0));
        row(0, "Builder", builder);
        row(1, "Kt", kt);
        row(2, "Ki", ki);
        row(3, "lambda", lambda);
        row(4, "", lambdaSlider);
        row(5, "SAH search", algorithm);
        row(6, "Bins", bins);
        row(7, "", perfectSplits);
        row(8, "Kmintri", minPrims);
        row(9, "Leaf size", leafSize);
        row(10, "Kmaxdepth", maxDepth);
        row(11, "", autoDepth);
        row(12, "", rejection);
        fault.setName("builder.fault");
        fault.setForeground(new java.awt.Color(170, 0, 0));
        wideRow(13, fault);
        builder.addActionListener(e -> apply());
        algorithm.addActionListener(e -> apply());
        perfectSplits.addActionListener(e -> apply());
        builder.setRenderer(new javax.swing.DefaultListCellRenderer() {
            @Override public java.awt.Component getListCellRendererComponent(javax.swing.JList<?> list, Object value, int index,
                                                                       boolean selected, boolean focus) {
                String name = value == null ? "" : value.toString();
                return super.getListCellRendererComponent(list, model.hung(name) ? name + " (hung)" : name, index, selected, focus);
            }
        });
        algorithm.setRenderer(new javax.swing.DefaultListCellRenderer() {
            @Override public java.awt.Component getListCellRendererComponent(javax.swing.JList<?> list, Object value, int index,
                                                                       boolean selected, boolean focus) {
                String text = value == null ? "" : value.toString().toLowerCase(java.util.Locale.ROOT);
                return super.getListCellRendererComponent(list, text, index, selected, focus);
            }
        });
        for (JSpinner s : new JSpinner[] {kt, ki, lambda, bins, minPrims, leafSize, maxDepth}) s.addChangeListener(e -> apply());
        lambdaSlider.addChangeListener(e -> {
            if (!updating) lambda.setValue(lambdaSlider.getValue() / 100.0);
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
        builder.repaint(); // its box marks a hung builder
    }

    private static String escaped(String s) {
        return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;");
    }

    /** {@return the fault shown, as its plain line, or null} (for tests) */
    String faultShown() { return fault.getToolTipText(); }

    /** Shows why the value just typed is not taken (null: the text is valid again). */
    private void reject(String why) {
        rejection.setText(why == null ? " " : why);
        rejection.setToolTipText(why);
    }

    /**
     * Selects the builder at {@code index} in the list (keyboard shortcut).
     *
     * @param index 0-based, in {@link org.kdtree.build.Builders#names()} order
     */
    public void selectBuilder(int index) {
        if (index < builder.getItemCount()) builder.setSelectedIndex(index);
    }

    private void apply() {
        if (updating) return;
        String name = (String) builder.getSelectedItem();
        KdTreeBuilder probe = Builders.create(name);
        SahBuilder.Algorithm a = (SahBuilder.Algorithm) algorithm.getSelectedItem();
        BuilderSpec s = BuilderSpec.of(name);
        s = give(s, probe, Setting.KT, ((Number) kt.getValue()).doubleValue());
        s = give(s, probe, Setting.KI, ((Number) ki.getValue()).doubleValue());
        s = give(s, probe, Setting.MAX_DEPTH, ((Number) maxDepth.getValue()).intValue());
        s = give(s, probe, Setting.PERFECT_SPLITS, perfectSplits.isSelected());
        s = give(s, probe, Setting.LAMBDA, ((Number) lambda.getValue()).doubleValue());
        s = give(s, probe, Setting.ALGORITHM, a);
        if (a == SahBuilder.Algorithm.BINNED) s = give(s, probe, Setting.BINS, ((Number) bins.getValue()).intValue());
        s = give(s, probe, Setting.MIN_PRIMITIVES, ((Number) minPrims.getValue()).intValue());
        s = give(s, probe, Setting.LEAF_SIZE, ((Number) leafSize.getValue()).intValue());
        show(s);
        model.setSettings(s);
    }

    /** {@code s} with {@code setting} given as {@code value} if the builder takes it (its control is greyed out otherwise). */
    private static <T> BuilderSpec give(BuilderSpec s, KdTreeBuilder probe, Setting<T> setting, T value) {
        return setting.appliesTo(probe) ? s.with(setting, value) : s;
    }

    private void show(BuilderSpec s) {
        updating = true;
        try {
            KdTreeBuilder probe = Builders.create(s.builder());
            builder.setSelectedItem(s.builder());
            showValue(s, probe, Setting.KT, kt);
            showValue(s, probe, Setting.KI, ki);
            showValue(s, probe, Setting.LAMBDA, lambda);
            showValue(s, probe, Setting.BINS, bins);
            showValue(s, probe, Setting.MIN_PRIMITIVES, minPrims);
            showValue(s, probe, Setting.LEAF_SIZE, leafSize);
            showValue(s, probe, Setting.MAX_DEPTH, maxDepth);
            if (Setting.PERFECT_SPLITS.appliesTo(probe)) perfectSplits.setSelected(s.value(Setting.PERFECT_SPLITS));
            if (Setting.ALGORITHM.appliesTo(probe)) algorithm.setSelectedItem(s.value(Setting.ALGORITHM));
            lambdaSlider.setValue((int) Math.round(((Number) lambda.getValue()).doubleValue() * 100));
            boolean sah = Setting.LAMBDA.appliesTo(probe);
            lambda.setEnabled(sah);
            lambdaSlider.setEnabled(sah);
            algorithm.setEnabled(sah);
            bins.setEnabled(sah && algorithm.getSelectedItem() == SahBuilder.Algorithm.BINNED);
            perfectSplits.setEnabled(Setting.PERFECT_SPLITS.appliesTo(probe));
            minPrims.setEnabled(Setting.MIN_PRIMITIVES.appliesTo(probe));
            leafSize.setEnabled(Setting.LEAF_SIZE.appliesTo(probe));
            int n = model.scene().size();
            int depth = ((Number) maxDepth.getValue()).intValue();
            autoDepth.setText(depth >= 0 ? "fixed depth cap " + depth
                    : "-1 = auto: 8 + 1.3 log2 " + n + " = " + KdTreeBuilder.defaultMaxDepth(n));
        } finally {
            updating = false;
        }
    }

    /** Shows the spec's value of {@code setting} (given, or the builder's default) in {@code control}, if the builder takes it. */
    private static void showValue(BuilderSpec s, KdTreeBuilder probe, Setting<?> setting, JSpinner control) {
        if (setting.appliesTo(probe)) control.setValue(s.value(setting));
    }

    private static void name(JComponent c, String name, String tip) {
        c.setName(name);
        c.setToolTipText(tip);
        if (c instanceof JSpinner s) {
            ((JSpinner.DefaultEditor) s.getEditor()).getTextField().setToolTipText(tip);
            ((JSpinner.DefaultEditor) s.getEditor()).getTextField().setName(name + ".text");
        }
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

    private void row(int y, String label, JComponent c) {
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
    }
}
