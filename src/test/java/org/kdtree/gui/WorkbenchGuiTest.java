package org.kdtree.gui;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeFalse;

import java.awt.GraphicsEnvironment;
import java.awt.Point;
import java.util.List;
import org.assertj.swing.core.MouseButton;
import org.assertj.swing.edt.GuiActionRunner;
import org.assertj.swing.fixture.FrameFixture;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * Drives the real workbench window with a Swing test robot. Needs a display (CI runs it
 * under Xvfb, see .ci/run); skipped where there is none. Surefire runs it in its own
 * execution, without -Djava.awt.headless.
 */
@Tag("gui")
class WorkbenchGuiTest {
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

    private List<String> stats() {
        return List.of("nodes", "leaves", "empty leaves", "depth", "SAH cost").stream()
                .map(s -> window.label("stat." + s).text()).toList();
    }

    @Test void switchBuilderChangeLambdaCastARayAndStep() {
        window.menuItemWithPath("Scene", "Clustered (200)").click();
        List<String> sah = stats();

        window.comboBox("builder").selectItem("median-plane");
        assertThat(bench.model().tree().builderName()).isEqualTo("median-plane");
        assertThat(stats()).isNotEqualTo(sah);
        assertThat(window.robot().finder().findAll(bench, c -> "lambda".equals(c.getName()) && c.isShowing()))
                .as("the SAH's lambda is not shown for the median plane").isEmpty();

        window.comboBox("builder").selectItem("sah");
        assertThat(stats()).isEqualTo(sah);
        window.spinner("lambda").select(0.2);
        assertThat(bench.model().settings().get(org.kdtree.kdtree.SahSettings.LAMBDA)).isEqualTo(0.2);
        assertThat(stats()).as("lambda 0.2 cuts off more empty space than 0.8").isNotEqualTo(sah);

        window.toggleButton("tool.RAY").click();
        int w = bench.canvas().getWidth(), h = bench.canvas().getHeight();
        Point from = new Point(8, h * 2 / 5), to = new Point(w - 8, h * 3 / 5);
        window.robot().pressMouse(bench.canvas(), from, MouseButton.LEFT_BUTTON);
        window.robot().moveMouse(bench.canvas(), new Point((from.x + to.x) / 2, (from.y + to.y) / 2));
        window.robot().moveMouse(bench.canvas(), to);
        window.robot().releaseMouse(MouseButton.LEFT_BUTTON);
        assertThat(bench.model().ray()).isNotNull();

        String first = window.label("step.label").text();
        assertThat(first).startsWith("step 1 /");
        assertThat(window.label("step.result").text()).contains("nodes").contains("tests");
        window.button("step.next").click();
        assertThat(window.label("step.label").text()).startsWith("step 2 /");
        assertThat(window.label("step.node").text()).startsWith("node #0");
        assertThat(window.label("step.interval").text()).contains("tSplit = ").doesNotContain("tSplit = -  ");
        assertThat(bench.model().selectedNode()).as("the tree view follows the stepper, not the mouse").isZero();
        window.robot().moveMouse(bench.canvas(), new Point(w / 3, h / 3));
        assertThat(bench.model().selectedNode()).isZero();
        window.button("step.next").click();
        String node = window.label("step.node").text();
        assertThat(node).startsWith("node #" + bench.model().selectedNode());
        window.button("step.last").click();
        assertThat(window.label("step.label").text()).endsWith("done");
        window.button("step.prev").click();
        assertThat(window.label("step.label").text()).doesNotEndWith("done");

        // editing: drag a rectangle in, then select it and delete it
        int objects = bench.model().scene().size();
        window.toggleButton("tool.RECT").click();
        Point a = new Point(w / 2 - 30, h / 2 - 20), c = new Point(w / 2 + 30, h / 2 + 20);
        window.robot().pressMouse(bench.canvas(), a, MouseButton.LEFT_BUTTON);
        window.robot().moveMouse(bench.canvas(), new Point(w / 2, h / 2));
        window.robot().moveMouse(bench.canvas(), c);
        window.robot().releaseMouse(MouseButton.LEFT_BUTTON);
        assertThat(bench.model().scene().size()).isEqualTo(objects + 1);
        assertThat(window.label("stat.objects").text()).isEqualTo(Integer.toString(objects + 1));
        window.toggleButton("tool.SELECT").click();
        window.robot().click(bench.canvas(), new Point(w / 2 + 29, h / 2));
        assertThat(bench.model().selectedShape()).isEqualTo(objects);
        window.menuItemWithPath("Scene", "Delete selected object").click();
        assertThat(bench.model().scene().size()).isEqualTo(objects);

        window.tabbedPane("tabs").selectTab("Compare builders");
        assertThat(bench.compare().statsText("sah")).contains("ray:").contains("tests");
        assertThat(bench.compare().statsText("median-plane")).contains("ray:");
        // any registered builder can be compared: the course example is found by ServiceLoader only
        window.comboBox("compare.builder.0").selectItem("centre-midpoint");
        assertThat(bench.compare().statsText("centre-midpoint")).contains("SAH cost").contains("ray:");
    }

    @Test void placeAKnnQueryAndStepToTheBruteForceAnswer() {
        window.menuItemWithPath("Scene", "Clustered (200)").click();
        window.tabbedPane("steppers").selectTab("Nearest neighbours");
        window.spinner("knn.k").select(5);
        window.toggleButton("tool.KNN").click();
        int w = bench.canvas().getWidth(), h = bench.canvas().getHeight();
        window.robot().click(bench.canvas(), new Point(w / 2 + 17, h / 2 - 11));
        double[] q = bench.model().query();
        assertThat(q).isNotNull();
        assertThat(window.label("knn.label").text()).startsWith("step 1 /").endsWith("start at the root");
        assertThat(window.label("knn.kth").text()).contains("radius): inf").contains("0 of 5");

        window.button("knn.next").click();
        assertThat(window.label("knn.label").text()).startsWith("step 2 /");
        assertThat(window.label("knn.node").text()).startsWith("node #0");
        assertThat(bench.model().selectedNode()).as("the tree view follows the k-NN stepper").isZero();
        window.robot().moveMouse(bench.canvas(), new Point(w / 3, h / 3));
        assertThat(bench.model().selectedNode()).isZero();
        String radius = window.label("knn.kth").text();
        for (int i = 0; i < 400 && !window.label("knn.kth").text().contains("5 of 5"); i++) window.button("knn.next").click();
        assertThat(window.label("knn.kth").text()).as("stepping fills the list and shrinks the radius")
                .isNotEqualTo(radius).contains("5 of 5").doesNotContain("inf");

        window.button("knn.last").click();
        assertThat(window.label("knn.label").text()).endsWith("done");
        List<NearestTrace.Neighbour> expected = NearestBruteForce.nearest(bench.model().scene(), q, 5);
        assertThat(bench.nearest().trace().result()).isEqualTo(expected);
        assertThat(window.label("knn.result").text()).startsWith("result: " + NearestStepperPanel.listText(expected, 4))
                .contains("pruned").contains("of 200 objects tested");
        assertThat(window.label("knn.best").text()).isEqualTo("best: " + NearestStepperPanel.listText(expected, 6));
        window.button("knn.prev").click();
        assertThat(window.label("knn.label").text()).doesNotEndWith("done");

        window.spinner("knn.k").select(1);
        assertThat(bench.nearest().trace().result()).isEqualTo(expected.subList(0, 1));
        window.menuItemWithPath("Nearest", "Clear query").click();
        assertThat(window.label("knn.label").text()).isEqualTo("no query");
    }

    @Test void theCollisionsViewRunsFramesWithFewerTestsThanBruteForce() throws Exception {
        window.menuItemWithPath("Scene", "Clustered (200)").click();
        window.tabbedPane("tabs").selectTab("Collisions");
        window.spinner("collide.balls").select(200);
        assertThat(window.label("collide.frame").text()).isEqualTo("frame 0");
        window.button("collide.step").click();
        assertThat(window.label("collide.frame").text()).isEqualTo("frame 1");
        window.button("collide.start").click();
        assertThat(window.button("collide.start").text()).isEqualTo("Stop");
        long deadline = System.nanoTime() + 30_000_000_000L;   // a guard against a hang, not a timing
        while (GuiActionRunner.execute(() -> bench.collisions().frames()) < 8 && System.nanoTime() < deadline) Thread.sleep(30);
        window.button("collide.start").click();
        assertThat(GuiActionRunner.execute(() -> bench.collisions().running())).isFalse();
        long frames = GuiActionRunner.execute(() -> bench.collisions().frames());
        assertThat(frames).isGreaterThanOrEqualTo(8);
        assertThat(window.label("collide.frame").text()).isEqualTo("frame " + frames);
        long tree = number(window.label("collide.tests").text()), brute = number(window.label("collide.brute").text());
        assertThat(brute).as("brute force: 200 objects per sweep, at least one sweep per ball").isGreaterThanOrEqualTo(200L * 200);
        assertThat(tree).isLessThan(brute);
        assertThat(tree).isEqualTo(GuiActionRunner.execute(() -> bench.collisions().lastTests()));

        window.button("collide.reset").click();
        assertThat(window.label("collide.frame").text()).isEqualTo("frame 0");
    }

    private static long number(String label) {
        return Long.parseLong(label.replaceAll("[^0-9]", ""));
    }

    @Test void aValueOutsideItsLimitIsFlaggedNotSilentlyReverted() {
        int nodes = bench.model().tree().nodeCount();
        window.textBox("kmaxdepth.text").setText("").enterText("1000\n");
        window.label("rejection").requireText("Kmaxdepth must be between -1 and 64 (-1 = auto: 8 + 1.3 log2 N for a kd-tree, 64 for a BVH), got 1000");
        assertThat(window.textBox("kmaxdepth.text").target().getToolTipText()).startsWith("Kmaxdepth must be between");
        assertThat(bench.model().settings().value(org.kdtree.accel.SharedSettings.MAX_DEPTH)).as("the rejected value is not applied").isEqualTo(-1);
        assertThat(bench.model().tree().nodeCount()).isEqualTo(nodes);

        window.textBox("kmaxdepth.text").setText("").enterText("12x");
        window.label("rejection").requireText("Kmaxdepth: '12x' is not a number, allowed: -1..64 (-1 = auto: 8 + 1.3 log2 N for a kd-tree, 64 for a BVH)");
        window.textBox("kmaxdepth.text").setText("").enterText("3\n");
        assertThat(window.robot().finder().findAll(bench, c -> "rejection".equals(c.getName()) && c.isShowing()))
                .as("a valid value again: the rejection's row is gone").isEmpty();
        assertThat(bench.model().settings().value(org.kdtree.accel.SharedSettings.MAX_DEPTH)).isEqualTo(3);
        window.label("autoDepth").requireText("fixed depth cap 3");
        assertThat(window.textBox("kmaxdepth.text").target().getToolTipText()).contains("allowed: -1..64");
    }

    @Test void theSceneBoxNamesTheSceneShownAfterGenerate() {
        window.spinner("count").select(300);
        window.button("generate").click();
        assertThat(bench.model().scene().size()).isEqualTo(300);
        window.comboBox("scene").requireSelection(bench.model().sceneName());
        assertThat(bench.model().sceneName()).endsWith("(300)");
        window.comboBox("scene").selectItem("Talk figures");
        window.comboBox("scene").requireSelection("Talk figures");
        assertThat(window.comboBox("scene").contents()).doesNotContain(bench.model().sceneName() + "x")
                .hasSize(BuiltinScenes.all().size());
    }

    /**
     * A 100,000-object rebuild runs off the event thread: while it runs, the event thread answers
     * probes (the median of them within 100 ms: the bound is on responsiveness, a build of that
     * size takes seconds when it blocks the thread), then the new tree arrives.
     */
    @Test void aLargeRebuildLeavesTheWindowResponsive() throws Exception {
        window.spinner("count").select(100_000);
        window.button("generate").click();
        List<Long> probes = new java.util.ArrayList<>();
        long deadline = System.nanoTime() + 120_000_000_000L;
        while (GuiActionRunner.execute(() -> bench.model().building()) && System.nanoTime() < deadline) {
            long t0 = System.nanoTime();
            javax.swing.SwingUtilities.invokeAndWait(() -> { });
            probes.add((System.nanoTime() - t0) / 1_000_000);
            Thread.sleep(20);
        }
        assertThat(probes).as("probes answered while the build ran").hasSizeGreaterThan(2);
        assertThat(probes.stream().sorted().toList().get(probes.size() / 2)).as("median probe, ms").isLessThan(100);
        assertThat(GuiActionRunner.execute(() -> bench.model().scene().size())).isEqualTo(100_000);
        assertThat(GuiActionRunner.execute(() -> bench.model().tree().stats().references())).isGreaterThanOrEqualTo(100_000);
    }

    @Test void aChangeDuringALargeBuildCancelsItAndTheLastSettingWins() throws Exception {
        window.spinner("count").select(100_000);
        window.button("generate").click();
        window.comboBox("builder").selectItem("median-plane");
        long deadline = System.nanoTime() + 120_000_000_000L;
        while (GuiActionRunner.execute(() -> bench.model().building()) && System.nanoTime() < deadline) Thread.sleep(50);
        assertThat(GuiActionRunner.execute(() -> bench.model().tree().builderName())).isEqualTo("median-plane");
        assertThat(GuiActionRunner.execute(() -> bench.model().scene().size())).isEqualTo(100_000);
    }

    @Test void everyControlHasATooltipAndEveryMenuItemAShortcut() {
        java.util.List<String> missing = new java.util.ArrayList<>();
        walk(bench.getContentPane(), missing);
        javax.swing.JMenuBar bar = bench.getJMenuBar();
        for (int i = 0; i < bar.getMenuCount(); i++) {
            javax.swing.JMenu menu = bar.getMenu(i);
            for (int j = 0; j < menu.getItemCount(); j++) {
                javax.swing.JMenuItem item = menu.getItem(j);
                if (item == null) continue;
                if (item.getAccelerator() == null) missing.add("shortcut of " + item.getText());
                if (item.getToolTipText() == null) missing.add("tooltip of " + item.getText());
            }
        }
        assertThat(missing).isEmpty();
    }

    private static void walk(java.awt.Container c, java.util.List<String> missing) {
        for (java.awt.Component k : c.getComponents()) {
            boolean control = k instanceof javax.swing.AbstractButton || k instanceof javax.swing.JComboBox
                    || k instanceof javax.swing.JSpinner || k instanceof javax.swing.JSlider || k instanceof javax.swing.JTree;
            if (control && ((javax.swing.JComponent) k).getToolTipText() == null)
                missing.add(k.getClass().getSimpleName() + " " + k.getName());
            if (k instanceof java.awt.Container sub && !(k instanceof javax.swing.JSpinner) && !(k instanceof javax.swing.JComboBox)
                    && !(k instanceof javax.swing.JScrollBar))
                walk(sub, missing);
        }
    }
}
