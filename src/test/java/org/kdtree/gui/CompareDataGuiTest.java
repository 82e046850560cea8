package org.kdtree.gui;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeFalse;

import java.awt.GraphicsEnvironment;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import javax.imageio.ImageIO;
import org.assertj.swing.edt.GuiActionRunner;
import org.assertj.swing.fixture.FrameFixture;
import org.assertj.swing.timing.Condition;
import org.assertj.swing.timing.Pause;
import org.assertj.swing.timing.Timeout;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.kdtree.compare.TreeDistance;
import org.kdtree.compare.TreeSignature;
import org.kdtree.shape.Scene2D;
import org.kdtree.spec.BuilderSpec;

/**
 * The workbench's "Compare data" view, driven by the robot: two scenes chosen in its boxes, the
 * distance shown is the library's for the trees the Builder panel's settings build (checked
 * against a build made here), equal scenes at 0, a change of builder redraws both, and a
 * hierarchy is refused in one line. Needs a display, as every robot test.
 */
@Tag("gui")
class CompareDataGuiTest {
    private FrameFixture window;
    private Workbench bench;

    @BeforeEach void open() {
        assumeFalse(GraphicsEnvironment.isHeadless(), "no display");
        window = WorkbenchWindow.open(null);
        bench = (Workbench) window.target();
    }

    @AfterEach void close() {
        if (window != null) window.cleanUp();
    }

    /** The distance of the two built-in scenes' trees, as the given builder builds them, made here. */
    private static double expected(String a, String b, BuilderSpec spec) {
        TreeSignature sa = TreeSignature.of(spec.create().build(new Scene2D(BuiltinScenes.all().get(a).get())));
        TreeSignature sb = TreeSignature.of(spec.create().build(new Scene2D(BuiltinScenes.all().get(b).get())));
        return TreeDistance.of(sa, sb);
    }

    private String termsShowing(String text) {
        Pause.pause(new Condition("the terms to show " + text) {
            @Override public boolean test() {
                return GuiActionRunner.execute(() -> bench.compareData().termsText()).contains(text);
            }
        }, Timeout.timeout(20_000));
        return GuiActionRunner.execute(() -> bench.compareData().termsText());
    }

    @Test void twoScenesTheirDistanceAndABuilderChange() throws Exception {
        window.tabbedPane("tabs").selectTab("Compare data");
        window.comboBox("compareData.a").selectItem("Clustered (200)");
        window.comboBox("compareData.b").selectItem("Clustered (200)");
        assertThat(termsShowing("distance 0.0000")).contains("volumes 0.000").contains("occupancy 0.000");

        window.comboBox("compareData.a").selectItem("Uniform (200)");
        double sah = expected("Uniform (200)", "Clustered (200)", bench.model().settings());
        assertThat(sah).isGreaterThan(0.05);
        termsShowing(String.format(Locale.ROOT, "distance %.4f", sah));
        assertThat(GuiActionRunner.execute(() -> bench.compareData().pictureShown())).isTrue();
        saveView(Path.of("target", "compare-data-view.png"));

        // the Builder panel's builder builds both sides again
        GuiActionRunner.execute(() -> bench.model().setSettings(BuilderSpec.of("median-plane")));
        double median = expected("Uniform (200)", "Clustered (200)", BuilderSpec.of("median-plane"));
        assertThat(median).isNotEqualTo(sah);
        termsShowing(String.format(Locale.ROOT, "distance %.4f", median));

        GuiActionRunner.execute(() -> bench.model().setSettings(BuilderSpec.of("bvh")));
        termsShowing("choose a kd-tree builder");
        assertThat(GuiActionRunner.execute(() -> bench.compareData().pictureShown())).isFalse();
    }

    /** The view as it is on screen, for a reader to look at (target/, not checked). */
    private void saveView(Path file) throws Exception {
        BufferedImage image = GuiActionRunner.execute(() -> {
            CompareDataView v = bench.compareData();
            BufferedImage im = new BufferedImage(v.getWidth(), v.getHeight(), BufferedImage.TYPE_INT_RGB);
            java.awt.Graphics2D g = im.createGraphics();
            v.paint(g);
            g.dispose();
            return im;
        });
        Files.createDirectories(file.getParent());
        ImageIO.write(image, "png", file.toFile());
    }
}
