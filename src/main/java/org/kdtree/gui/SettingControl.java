package org.kdtree.gui;

import java.util.Arrays;
import java.util.Locale;
import java.util.function.Consumer;
import java.util.function.Predicate;
import javax.swing.DefaultListCellRenderer;
import javax.swing.JCheckBox;
import javax.swing.JComboBox;
import javax.swing.JComponent;
import javax.swing.JList;
import javax.swing.JSpinner;
import org.kdtree.accel.Setting;
import org.kdtree.spec.BuilderSpec;

/**
 * The workbench's control of one builder {@link Setting}, made from its row: a spinner over the
 * row's limit, starting at its default, for a number; a check box for a switch; a list for a
 * choice. Its name (for tests and screen readers), label and tooltip come from the row too, so a
 * setting added to the table gets its control without a change here.
 */
final class SettingControl {
    private final Setting<?> setting;
    private final JComponent component;

    private SettingControl(Setting<?> setting, JComponent component) {
        this.setting = setting;
        this.component = component;
        component.setName(componentName(setting.name()));
        String tip = tooltip(setting);
        component.setToolTipText(tip);
        if (component instanceof JSpinner s) {
            ((JSpinner.DefaultEditor) s.getEditor()).getTextField().setToolTipText(tip);
            ((JSpinner.DefaultEditor) s.getEditor()).getTextField().setName(component.getName() + ".text");
        }
    }

    /**
     * The control of {@code setting}.
     *
     * @param onRejected told why a typed number is refused (null once the text is valid again)
     * @param offered    which of a choice's values the list offers
     */
    static SettingControl of(Setting<?> setting, Consumer<String> onRejected, Predicate<Object> offered) {
        Class<?> type = setting.type();
        if (type == Boolean.class) return new SettingControl(setting, new JCheckBox(setting.name(), (Boolean) setting.defaultValue()));
        if (type.isEnum()) return new SettingControl(setting, choice(type, offered));
        boolean fraction = !setting.limit().integer() && setting.limit().max() <= 1;   // lambda: hundredths matter, whole steps do not
        return new SettingControl(setting, LimitedSpinner.of(setting.limit(), setting.name(),
                ((Number) setting.defaultValue()).doubleValue(), fraction ? 0.05 : 1, onRejected));
    }

    private static JComboBox<Object> choice(Class<?> type, Predicate<Object> offered) {
        JComboBox<Object> box = new JComboBox<>(Arrays.stream(type.getEnumConstants()).filter(offered).toArray());
        box.setRenderer(new DefaultListCellRenderer() {
            @Override public java.awt.Component getListCellRendererComponent(JList<?> list, Object value, int index,
                                                                       boolean selected, boolean focus) {
                String text = value == null ? "" : value.toString().toLowerCase(Locale.ROOT);
                return super.getListCellRendererComponent(list, text, index, selected, focus);
            }
        });
        return box;
    }

    /** "leaf size" is {@code leafSize}, "Kmaxdepth" {@code kmaxdepth}. */
    static String componentName(String name) {
        String[] words = name.split(" ");
        StringBuilder s = new StringBuilder(words[0].toLowerCase(Locale.ROOT));
        for (int i = 1; i < words.length; i++) s.append(Character.toUpperCase(words[i].charAt(0))).append(words[i].substring(1));
        return s.toString();
    }

    /** "lambda: the SAH's weight of ... (1 = no bonus); the sah builder only; allowed: 0.01..1". */
    private static String tooltip(Setting<?> s) {
        return s.name() + ": " + s.help() + (BuilderSpec.appliesToEvery(s) ? "" : "; " + BuilderSpec.ownerName(s) + " only")
                + (s.limit() != null ? "; " + LimitedSpinner.allowed(s.limit()) : "");
    }

    /** {@return the setting} */
    Setting<?> setting() { return setting; }

    /** {@return the component to lay out} */
    JComponent component() { return component; }

    /** {@return the label beside it: the setting's name, or blank for a check box, which names itself} */
    String label() { return component instanceof JCheckBox ? "" : setting.name(); }

    /** Calls {@code r} whenever the user changes the value. */
    void onChange(Runnable r) {
        if (component instanceof JSpinner s) s.addChangeListener(e -> r.run());
        else if (component instanceof JCheckBox c) c.addActionListener(e -> r.run());
        else ((JComboBox<?>) component).addActionListener(e -> r.run());
    }

    /** {@return the value shown}, of the setting's type */
    Object value() {
        if (component instanceof JCheckBox c) return c.isSelected();
        if (component instanceof JComboBox<?> b) return b.getSelectedItem();
        Number n = (Number) ((JSpinner) component).getValue();
        return setting.type() == Integer.class ? (Object) n.intValue() : (Object) n.doubleValue();
    }

    /** Shows {@code value}, one of the setting's. */
    void show(Object value) {
        if (component instanceof JCheckBox c) c.setSelected((Boolean) value);
        else if (component instanceof JComboBox<?> b) b.setSelectedItem(value);
        else ((JSpinner) component).setValue(value);
    }

    /** {@return {@code spec} with this setting given as the value shown} */
    BuilderSpec giveTo(BuilderSpec spec) {
        return with(spec, setting, value());
    }

    private static <T> BuilderSpec with(BuilderSpec spec, Setting<T> setting, Object value) {
        return spec.with(setting, setting.type().cast(value));
    }
}
