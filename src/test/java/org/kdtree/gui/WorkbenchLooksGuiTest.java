package org.kdtree.gui;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeFalse;

import java.awt.GraphicsEnvironment;
import java.awt.Rectangle;
import java.awt.geom.Rectangle2D;
import java.awt.image.BufferedImage;
import javax.swing.JTextArea;
import org.assertj.swing.edt.GuiActionRunner;
import org.assertj.swing.fixture.FrameFixture;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * A first look at the workbench finds nothing unfinished: the 3-D tab renders as soon as it is
 * opened and its statistics fit their column, the balls stay inside their panel, and only the
 * shown stepper draws over the tree. Drives the real window (a display, e.g. Xvfb, as {@link WorkbenchGuiTest}).
 */
@Tag("gui")
class WorkbenchLooksGuiTest {
    private FrameFixture window;
    private Workbench bench;

    @BeforeEach void open() {
        assumeFalse(GraphicsEnvironment.isHeadless(), "no display");
        window = WorkbenchWindow.open(new java.awt.Dimension(1280, 880));
        bench = (Workbench) window.target();
    }

    @AfterEach void close() {
        if (window != null) window.cleanUp();
    }

    @Test void theThreeDTabRendersWhenOpenedAndItsStatisticsFit() throws Exception {
        window.tabbedPane("tabs").selectTab("3-D");
        long deadline = System.nanoTime() + 180_000_000_000L;   // a guard against a hang, not a timing
        do Thread.sleep(200);
        while ((GuiActionRunner.execute(() -> bench.view3D().busy() || bench.view3D().statisticsText().isEmpty()))
                && System.nanoTime() < deadline);
        window.robot().waitForIdle();
        assertThat(GuiActionRunner.execute(() -> bench.view3D().image())).as("rendered without Render pressed").isNotNull();
        JTextArea out = (JTextArea) window.textBox("view3d.output").target();
        String first = GuiActionRunner.execute(() -> out.getText().lines().findFirst().orElse(""));
        assertThat(first).startsWith("scene: ");
        int needed = GuiActionRunner.execute(() -> out.getFontMetrics(out.getFont()).stringWidth(first));
        int shown = GuiActionRunner.execute(() -> out.getVisibleRect().width);
        assertThat(shown).as("the statistics column shows the whole of \"%s\"", first).isGreaterThanOrEqualTo(needed);
    }

    @Test void theTreeListKeepsRoomForItsNodesWhateverTheBuilder() {
        for (String name : new String[] {"sah", "median-plane", "sliding-midpoint", "bvh"}) {
            window.comboBox("builder").selectItem(name);
            int height = GuiActionRunner.execute(() -> treeView().getHeight());
            assertThat(height).as("the tree list's height under %s (1280 x 880 window)", name).isGreaterThanOrEqualTo(150);
        }
    }

    private java.awt.Component treeView() {
        for (java.awt.Component c : org.assertj.swing.core.BasicComponentFinder.finderWithCurrentAwtHierarchy()
                .findAll(bench, comp -> comp instanceof TreeNodeView))
            return c;
        throw new AssertionError("no tree list in the window");
    }

    @Test void theBallsStayInsideTheirPanel() {
        window.menuItemWithPath("Scene", "Uniform (200)").click();
        window.tabbedPane("tabs").selectTab("Collisions");
        window.spinner("collide.balls").select(300);
        for (int f = 0; f < 120; f++) {
            window.button("collide.step").click();
            if (f % 10 != 0) continue;
            window.robot().waitForIdle();
            Rectangle2D balls = GuiActionRunner.execute(() -> bench.collisions().ballsOnScreen());
            Rectangle panel = GuiActionRunner.execute(() -> new Rectangle(bench.collisions().arena().getSize()));
            assertThat(panel.contains(balls)).as("frame %d: balls %s inside the panel %s", f + 1, balls, panel).isTrue();
        }
    }

    @Test void aQueryPointHidesTheTraversalsRay() {
        GuiActionRunner.execute(() -> bench.model().setRay(0.2, 2, 9.8, 7.5));
        window.robot().waitForIdle();
        assertThat(rayPixels()).as("the cast ray is drawn").isPositive();
        GuiActionRunner.execute(() -> bench.model().setQuery(5.3, 3.6));
        window.robot().waitForIdle();
        assertThat(rayPixels()).as("the k-NN stepper is up: the ray is not drawn over it").isZero();
        window.tabbedPane("steppers").selectTab("Ray traversal");
        assertThat(rayPixels()).as("back on the traversal stepper: its ray again").isPositive();
    }

    /** The canvas's pixels in the ray's colour. */
    private long rayPixels() {
        return GuiActionRunner.execute(() -> {
            TreeCanvas c = bench.canvas();
            BufferedImage img = new BufferedImage(c.getWidth(), c.getHeight(), BufferedImage.TYPE_INT_RGB);
            c.paint(img.getGraphics());
            long n = 0;
            for (int y = 0; y < img.getHeight(); y++)
                for (int x = 0; x < img.getWidth(); x++) if ((img.getRGB(x, y) & 0xFFFFFF) == (Palette.RAY.getRGB() & 0xFFFFFF)) n++;
            return n;
        });
    }
}
