package org.kdtree.gui;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeFalse;

import java.awt.GraphicsEnvironment;
import java.nio.file.Path;
import org.assertj.swing.edt.GuiActionRunner;
import org.assertj.swing.fixture.FrameFixture;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kdtree.spec.Builders;
import org.kdtree.testing.PluginJars;
import org.kdtree.testing.PluginLeafyBuilder;
import org.kdtree.testing.PluginMidpointBuilder;

/**
 * A builder known only through a plug-in jar (as {@code --plugin my.jar} loads it) is offered in
 * the workbench's builder box and in the compare view, and builds there. Robot test: needs a
 * display (CI: Xvfb), as {@link WorkbenchGuiTest}.
 */
@Tag("gui")
class PluginGuiTest {
    @TempDir Path dir;
    private FrameFixture window;
    private Workbench bench;

    @BeforeEach void open() throws Exception {
        assumeFalse(GraphicsEnvironment.isHeadless(), "no display");
        assertThat(Builders.names()).doesNotContain("plugin-midpoint");
        Builders.loadPlugins(PluginJars.listing(dir, "student.jar", PluginMidpointBuilder.class.getName()));
        Builders.loadPlugins(PluginJars.listing(dir, "leafy.jar", PluginLeafyBuilder.class.getName()));
        window = WorkbenchWindow.open(null);
        bench = (Workbench) window.target();
    }

    @AfterEach void close() {
        if (window != null) window.cleanUp();
        Builders.remove("plugin-midpoint");
        Builders.remove("plugin-leafy");
    }

    /** A plug-in's own setting has its control, shown for that builder only, and the builder reads it. */
    @Test void aPluginsOwnSettingHasItsControl() {
        window.menuItemWithPath("Scene", "Clustered (200)").click();
        window.comboBox("builder").selectItem("sah");
        assertThat(window.robot().finder().findByName("leafLimit", javax.swing.JSpinner.class, false).isVisible())
                .as("another builder's setting is not shown").isFalse();
        window.comboBox("builder").selectItem("plugin-leafy");
        window.spinner("leafLimit").requireVisible();
        window.spinner("leafLimit").select(2);
        assertThat(bench.model().tree().builderName()).isEqualTo("plugin-leafy");
        assertThat(bench.model().settings().get(PluginLeafyBuilder.LEAF_LIMIT)).isEqualTo(2);
        int small = bench.model().tree().nodeCount();
        window.spinner("leafLimit").select(100);
        assertThat(bench.model().settings().get(PluginLeafyBuilder.LEAF_LIMIT)).isEqualTo(100);
        assertThat(bench.model().tree().nodeCount()).as("a larger leaf limit splits less").isLessThan(small);
    }

    @Test void aPluggedInBuilderIsInTheBuilderBoxAndTheCompareView() {
        window.menuItemWithPath("Scene", "Clustered (200)").click();
        window.comboBox("builder").selectItem("plugin-midpoint");
        assertThat(bench.model().tree().builderName()).isEqualTo("plugin-midpoint");
        assertThat(window.label("stat.nodes").text()).isNotBlank();

        window.tabbedPane("tabs").selectTab("Compare builders");
        window.comboBox("compare.builder.1").selectItem("plugin-midpoint");
        assertThat(bench.compare().statsText("plugin-midpoint")).contains("SAH cost");
    }
}
