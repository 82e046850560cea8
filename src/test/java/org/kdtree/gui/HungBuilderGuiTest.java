package org.kdtree.gui;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeFalse;

import java.awt.GraphicsEnvironment;
import java.nio.file.Path;
import javax.swing.SwingUtilities;
import org.assertj.swing.edt.GuiActionRunner;
import org.assertj.swing.fixture.FrameFixture;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kdtree.kdtree.BuilderFault;
import org.kdtree.kdtree.KdTree;
import org.kdtree.spec.Builders;
import org.kdtree.testing.LoopingFindPlaneBuilder;
import org.kdtree.testing.PluginJars;
import org.kdtree.testing.ThrowingBuilder;

/**
 * A plug-in builder that never returns from findPlane, picked in the workbench: the window stays
 * responsive (another tab opens at once), the builder is stopped after the workbench's call
 * deadline and marked hung, and the previous tree stays on screen, marked stale. One that throws
 * is named the same way, at once. Robot test: needs a display (CI: Xvfb), as {@link WorkbenchGuiTest}.
 */
@Tag("gui")
class HungBuilderGuiTest {
    @TempDir Path dir;
    private FrameFixture window;
    private Workbench bench;

    @BeforeEach void open() throws Exception {
        assumeFalse(GraphicsEnvironment.isHeadless(), "no display");
        Builders.loadPlugins(PluginJars.listing(dir, "broken.jar", LoopingFindPlaneBuilder.class.getName(), ThrowingBuilder.class.getName()));
        window = WorkbenchWindow.open(null);
        bench = (Workbench) window.target();
        window.menuItemWithPath("Scene", "Clustered (200)").click();
    }

    @AfterEach void close() {
        if (window != null) window.cleanUp();
        Builders.remove("loops-in-findplane");
        Builders.remove("throws");
    }

    @Test void aLoopingBuilderIsStoppedAndMarkedHungWhileTheWindowStaysResponsive() throws Exception {
        KdTree before = GuiActionRunner.execute(() -> bench.model().tree());
        window.comboBox("builder").selectItem("loops-in-findplane");

        window.tabbedPane("tabs").selectTab("Compare builders");   // while findPlane spins
        window.tabbedPane("tabs").requireSelectedTab(org.assertj.swing.data.Index.atIndex(indexOf("Compare builders")));
        assertThat(GuiActionRunner.execute(() -> bench.model().building())).as("still building: the window did not wait for it").isTrue();
        assertThat(probeMillis()).as("the event thread answers within").isLessThan(1_000);

        BuilderFault fault = awaitFault();
        assertThat(fault.kind()).isEqualTo(BuilderFault.Kind.HUNG);
        assertThat(fault.getMessage()).isEqualTo("builder loops-in-findplane: findPlane did not return within 3 s, at depth 0 on a node of"
                + " 200 primitives; it was stopped: look for a loop that never ends in findPlane");
        assertThat(GuiActionRunner.execute(() -> bench.model().tree())).as("the previous tree, still shown").isSameAs(before);
        assertThat(GuiActionRunner.execute(() -> bench.model().stale())).isTrue();
        assertThat(GuiActionRunner.execute(() -> bench.model().hung("loops-in-findplane"))).isTrue();
        assertThat(Thread.getAllStackTraces().keySet()).noneMatch(t -> t.getName().equals("build by loops-in-findplane") && t.isAlive());

        window.tabbedPane("tabs").selectTab("2-D build");
        assertThat(window.label("builder.fault").text()).contains("findPlane did not return within 3 s").contains("stale");
        assertThat(window.label("stat.build time").text()).isEqualTo("failed (stale tree)");

        window.comboBox("builder").selectItem("sah");                // a sound builder again: a fresh tree, nothing stale
        assertThat(GuiActionRunner.execute(() -> bench.model().stale())).isFalse();
        assertThat(window.robot().finder().findAll(bench, c -> "builder.fault".equals(c.getName()) && c.isShowing()))
                .as("no fault: its row is gone").isEmpty();
    }

    @Test void aThrowingBuilderIsNamedAndThePreviousTreeStaysStale() {
        KdTree before = GuiActionRunner.execute(() -> bench.model().tree());
        window.comboBox("builder").selectItem("throws");
        BuilderFault fault = awaitFault();
        assertThat(fault.kind()).isEqualTo(BuilderFault.Kind.THREW);
        assertThat(fault.getMessage()).startsWith("builder throws: findPlane threw ArrayIndexOutOfBoundsException");
        assertThat(GuiActionRunner.execute(() -> bench.model().tree())).isSameAs(before);
        assertThat(window.label("builder.fault").text()).contains("builder throws: findPlane threw").contains("stale");
    }

    private int indexOf(String tab) {
        return GuiActionRunner.execute(() -> {
            javax.swing.JTabbedPane tabs = (javax.swing.JTabbedPane) window.tabbedPane("tabs").target();
            return tabs.indexOfTab(tab);
        });
    }

    private static long probeMillis() throws Exception {
        long t0 = System.nanoTime();
        SwingUtilities.invokeAndWait(() -> { });
        return (System.nanoTime() - t0) / 1_000_000;
    }

    private BuilderFault awaitFault() {
        long deadline = System.nanoTime() + 15_000_000_000L;
        BuilderFault f;
        while ((f = GuiActionRunner.execute(() -> bench.model().fault())) == null && System.nanoTime() < deadline) {
            try {
                Thread.sleep(50);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                break;
            }
        }
        assertThat(f).as("the builder's fault, within the deadline").isNotNull();
        return f;
    }
}
