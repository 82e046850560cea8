package org.kdtree.gui;

import javax.swing.JButton;
import javax.swing.JLabel;

/** The small components the workbench's panels make the same way: named, with a tooltip. */
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
}
