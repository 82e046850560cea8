package org.kdtree.gui;

import java.awt.FlowLayout;
import java.util.function.IntConsumer;
import javax.swing.JButton;
import javax.swing.JPanel;
import javax.swing.JSlider;
import javax.swing.Timer;

/**
 * What every stepper of the workbench shares: first, back, forward, last, play or pause, and a
 * slider over the steps of a recorded trace. It keeps the step shown and tells its owner when
 * that changes; the owner draws the step.
 */
final class StepControls {
    /** The steps' slider. */
    private final JSlider slider = new JSlider(0, 0, 0);
    /** Advances one step per tick while playing. */
    private final Timer player = new Timer(350, e -> playStep());
    /** Starts or stops playing. */
    private final JButton play;
    /** The buttons and the slider, in a row. */
    private final JPanel bar = new JPanel(new FlowLayout(FlowLayout.LEFT, 2, 0));
    /** Told the step to show. */
    private final IntConsumer onShow;
    /** The step shown, and the number of steps. */
    private int index, size;
    /** True while the slider is set from here, so that its listener does not act. */
    private boolean updating;

    /**
     * @param prefix   the components' name prefix ("step", "knn")
     * @param what     what is stepped through, for tooltips ("traversal", "search")
     * @param shortcut the keyboard modifier of the owner's step shortcuts ("Ctrl", "Ctrl+Shift")
     * @param onShow   shows a step (0 .. size - 1; also called with 0 when there is none)
     */
    StepControls(String prefix, String what, String shortcut, IntConsumer onShow) {
        this.onShow = onShow;
        bar.add(Widgets.button("|<", prefix + ".first", "First step (" + shortcut + "+Home)", this::first));
        bar.add(Widgets.button("<", prefix + ".prev", "Step back (" + shortcut + "+Left)", this::back));
        bar.add(Widgets.button(">", prefix + ".next", "Step forward (" + shortcut + "+Right)", this::forward));
        bar.add(Widgets.button(">|", prefix + ".last", "Last step: the result (" + shortcut + "+End)", this::last));
        play = Widgets.button("Play", prefix + ".play", "Play or pause the " + what + " (" + shortcut + "+P)", this::togglePlay);
        bar.add(play);
        slider.setName(prefix + ".slider");
        slider.setToolTipText("Drag to any step of the " + what);
        slider.addChangeListener(e -> {
            if (!updating) show(slider.getValue());
        });
        bar.add(slider);
    }

    /** {@return the row of buttons and the slider, to which the owner may add its own controls} */
    JPanel bar() { return bar; }

    /** {@return the step shown} */
    int index() { return index; }

    /**
     * Starts over on a new trace of {@code steps} steps, showing its first.
     *
     * @param steps the new trace's length
     */
    void reset(int steps) {
        size = steps;
        updating = true;
        slider.setMaximum(Math.max(0, steps - 1));
        updating = false;
        show(0);
    }

    /**
     * Shows step {@code i}, kept within the trace.
     *
     * @param i the step wanted
     */
    void show(int i) {
        index = Math.max(0, Math.min(i, size - 1));
        updating = true;
        slider.setValue(index);
        updating = false;
        onShow.accept(index);
    }

    /** Shows the first step. */
    void first() { show(0); }

    /** Shows the step before the current one. */
    void back() { show(index - 1); }

    /** Shows the step after the current one. */
    void forward() { show(index + 1); }

    /** Shows the last step: the result. */
    void last() { show(size - 1); }

    /** Plays the steps one per tick, or pauses. */
    void togglePlay() {
        if (player.isRunning()) {
            player.stop();
        } else {
            if (index >= size - 1) show(0);
            player.start();
        }
        play.setText(player.isRunning() ? "Pause" : "Play");
    }

    private void playStep() {
        if (index >= size - 1) togglePlay();
        else forward();
    }
}
