package org.kdtree.gui;

import java.awt.Component;
import java.awt.FlowLayout;
import javax.swing.JButton;
import javax.swing.JLabel;
import javax.swing.JPanel;

/** The small components the workbench's panels make the same way (named, with a tooltip), and their rows. */
final class Widgets {
    private Widgets() {
    }

    /**
     * {@return a button that runs {@code action}, named for tests, never taking the keyboard focus}
     *
     * @param text   the button's text
     * @param name   its component name
     * @param tip    its tooltip
     * @param action what a click does
     */
    static JButton button(String text, String name, String tip, Runnable action) {
        JButton b = new JButton(text);
        b.setName(name);
        b.setToolTipText(tip);
        b.setFocusable(false);
        b.addActionListener(e -> action.run());
        return b;
    }

    /**
     * {@return an empty label, named for tests, with a tooltip}
     *
     * @param name its component name
     * @param tip  its tooltip
     */
    static JLabel label(String name, String tip) {
        JLabel l = new JLabel(" ");
        l.setName(name);
        l.setToolTipText(tip);
        return l;
    }

    /**
     * {@return a view's row of controls, left to right as given}: each text a label, each component itself
     *
     * @param parts texts (labels) and components, in order
     */
    static JPanel row(Object... parts) {
        JPanel row = new JPanel(new FlowLayout(FlowLayout.LEFT));
        for (Object p : parts) row.add(p instanceof String text ? new JLabel(text) : (Component) p);
        return row;
    }

    /**
     * {@return a stepper's number as its labels show it: 3 decimals, "inf" or "-" for none}
     *
     * @param v the number, possibly infinite or NaN
     */
    static String num(double v) {
        if (Double.isNaN(v)) return "-";
        if (Double.isInfinite(v)) return v > 0 ? "inf" : "-inf";
        return String.format(java.util.Locale.ROOT, "%.3f", v);
    }

    /**
     * Repaints the whole window holding {@code c}, so that a stepper's canvas overlay follows its step.
     *
     * @param c a component of the window
     */
    static void repaintWindow(java.awt.Component c) {
        java.awt.Window w = javax.swing.SwingUtilities.getWindowAncestor(c);
        if (w != null) w.repaint();
    }
}
