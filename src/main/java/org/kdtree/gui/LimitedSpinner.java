package org.kdtree.gui;

import java.awt.Color;
import java.text.ParsePosition;
import java.util.function.Consumer;
import javax.swing.JFormattedTextField;
import javax.swing.JSpinner;
import javax.swing.SpinnerNumberModel;
import javax.swing.event.DocumentEvent;
import javax.swing.event.DocumentListener;
import org.kdtree.limits.Limit;

/**
 * A spinner whose range is a {@link Limit}: the same range the API and the command line
 * enforce. A typed value outside it is not silently reverted: the field turns red and says
 * why, in its tooltip and through {@code onRejected}, until the text is mended.
 */
final class LimitedSpinner {
    private static final Color REJECTED = new Color(255, 205, 205);

    private LimitedSpinner() {
    }

    /**
     * @param label      how the workbench names the value in messages ("Kmaxdepth")
     * @param onRejected told the rejection's one line, or null once the text is valid again
     */
    static JSpinner of(Limit limit, String label, double value, double step, Consumer<String> onRejected) {
        SpinnerNumberModel model = limit.integer()
                ? new SpinnerNumberModel((int) value, (int) limit.min(), (int) limit.max(), (int) step)
                : new SpinnerNumberModel(value, limit.min(), limit.max(), step);
        JSpinner spinner = new JSpinner(model);
        JSpinner.NumberEditor editor = (JSpinner.NumberEditor) spinner.getEditor();
        JFormattedTextField field = editor.getTextField();
        field.setColumns(5);
        Color normal = field.getBackground();
        field.getDocument().addDocumentListener(new DocumentListener() {
            @Override public void insertUpdate(DocumentEvent e) { check(); }
            @Override public void removeUpdate(DocumentEvent e) { check(); }
            @Override public void changedUpdate(DocumentEvent e) { check(); }

            private void check() {
                String problem = problem(limit, label, field.getText(), editor);
                boolean wasRejected = field.getClientProperty("rejection") != null;
                if (problem != null && !wasRejected) field.putClientProperty("tooltip", field.getToolTipText());
                field.setBackground(problem == null ? normal : REJECTED);
                field.setToolTipText(problem != null ? problem : (String) field.getClientProperty("tooltip"));
                field.putClientProperty("rejection", problem);
                onRejected.accept(problem);
            }
        });
        return spinner;
    }

    /** The tooltip line that states the range. */
    static String allowed(Limit limit) {
        return "allowed: " + limit.range();
    }

    /** Why {@code text} is not a value the limit allows, or null if it is. */
    private static String problem(Limit limit, String label, String text, JSpinner.NumberEditor editor) {
        if (text.isBlank()) return label + ": type a number, " + allowed(limit);
        String t = text.strip();
        ParsePosition at = new ParsePosition(0);
        Number n = (Number) editor.getFormat().parseObject(t, at);
        if (n == null || at.getIndex() != t.length()) return label + ": '" + t + "' is not a number, " + allowed(limit);
        return limit.allows(n.doubleValue()) ? null : limit.rejection(label, t);
    }
}
