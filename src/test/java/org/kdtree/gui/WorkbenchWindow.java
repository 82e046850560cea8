package org.kdtree.gui;

import java.awt.Dimension;
import java.awt.Point;
import javax.swing.ToolTipManager;
import org.assertj.swing.edt.GuiActionRunner;
import org.assertj.swing.fixture.FrameFixture;

/** The real workbench window, as every robot test opens it. */
final class WorkbenchWindow {
    private WorkbenchWindow() {
    }

    /**
     * Opens a new workbench: tooltips off (one popping up under the robot's mouse would swallow its
     * clicks on the canvas), shown at its preferred size, or at {@code size} if given, in the
     * screen's corner (the robot shows it away from the corner: on a 1280-wide screen the side
     * panel's right edge, Generate, was off it).
     * @param size the window's size, or null for its own
     * @return the window; {@code (Workbench) window.target()} is the workbench
     */
    static FrameFixture open(Dimension size) {
        GuiActionRunner.execute(() -> ToolTipManager.sharedInstance().setEnabled(false));
        Workbench bench = GuiActionRunner.execute(() -> new Workbench());
        FrameFixture window = new FrameFixture(bench);
        if (size == null) window.show();
        else window.show(size);
        window.moveTo(new Point(0, 0));
        return window;
    }
}
