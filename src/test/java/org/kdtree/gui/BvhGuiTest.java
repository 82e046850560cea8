package org.kdtree.gui;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeFalse;

import java.awt.GraphicsEnvironment;
import java.util.Locale;
import org.assertj.swing.edt.GuiActionRunner;
import org.assertj.swing.fixture.FrameFixture;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.kdtree.accel.Hit;
import org.kdtree.accel.TraversalStats;
import org.kdtree.bvh.Bvh;
import org.kdtree.geom.Ray;
import org.kdtree.shape.Scene2D;

/**
 * The bounding volume hierarchy in the workbench, driven by the robot in the real window (a
 * display, e.g. Xvfb, as {@link WorkbenchGuiTest}): chosen in the compare view beside the
 * kd-trees, with its statistics, its boxes drawn and the cast ray's cost counted as the library
 * counts it; chosen in the builder panel, drawn on the canvas with only its settings offered and
 * its traversal stepped through box by box.
 */
@Tag("gui")
class BvhGuiTest {
    /** The ray both tests cast across the clustered scene. */
    private static final double[] RAY = {0.2, 4.1, 9.8, 5.6};

    private FrameFixture window;
    private Workbench bench;

    @BeforeEach void open() {
        assumeFalse(GraphicsEnvironment.isHeadless(), "no display");
        window = WorkbenchWindow.open(null);
        bench = (Workbench) window.target();
        window.menuItemWithPath("Scene", "Clustered (200)").click();
        GuiActionRunner.execute(() -> bench.model().setRay(RAY[0], RAY[1], RAY[2], RAY[3]));
    }

    @AfterEach void close() {
        if (window != null) window.cleanUp();
    }

    /** The hierarchy the workbench builds with its default settings, and the ray's counts in it as the library counts them. */
    private record Expected(Bvh bvh, TraversalStats ray) {
        static Expected of(Scene2D scene) {
            Bvh bvh = new org.kdtree.bvh.BvhBuilder().build(scene);
            TraversalStats stats = new TraversalStats();
            bvh.query(stats).closestHit(
                    new Ray(2).set(RAY[0], RAY[1], RAY[2] - RAY[0], RAY[3] - RAY[1]), 0, Double.POSITIVE_INFINITY, new Hit());
            return new Expected(bvh, stats);
        }
    }

    @Test void theComparisonShowsTheHierarchyBesideTheKdTrees() throws Exception {
        window.tabbedPane("tabs").selectTab("Compare builders");
        window.comboBox("compare.builder.0").selectItem("bvh");
        String text = waitForBuild("bvh");
        Expected e = Expected.of(GuiActionRunner.execute(() -> bench.model().scene()));
        assertThat(text).contains("nodes (boxes): " + e.bvh().nodeCount() + ", leaves: " + e.bvh().stats().leaves())
                .contains("depth: " + e.bvh().maxDepth())
                .contains(String.format(Locale.ROOT, "SAH cost: %.2f", e.bvh().stats().expectedCost()))
                .contains("memory: " + StatsPanel.memory(e.bvh().memoryBytes()))
                .contains(String.format(Locale.ROOT, "ray:</b> %d nodes, %d leaves, %d box tests, %d tests",
                        e.ray().nodes, e.ray().leaves, e.ray().boxTests, e.ray().primitiveTests));
        assertThat(e.ray().boxTests).as("a ray across the scene tests boxes").isPositive();
        assertThat(bench.compare().statsText("sah")).as("the kd-tree beside it, its ray counted the same way")
                .contains("ray:</b>").contains("ray cost").contains("memory: ").doesNotContain("box tests");
        window.robot().waitForIdle();
        assertThat(GuiActionRunner.execute(() -> bench.compare().boxesPainted("bvh"))).as("every node's box painted")
                .isEqualTo(e.bvh().nodeCount());
        assertThat(GuiActionRunner.execute(() -> bench.compare().boxesPainted("sah"))).isZero();
    }

    /** Waits (a guard against a hang, not a timing) until the column of {@code builder} shows its build. */
    private String waitForBuild(String builder) throws InterruptedException {
        long deadline = System.nanoTime() + 30_000_000_000L;
        String text;
        do {
            window.robot().waitForIdle();
            text = GuiActionRunner.execute(() -> bench.compare().statsText(builder));
            if (!text.contains("building")) return text;
            Thread.sleep(50);
        } while (System.nanoTime() < deadline);
        return text;
    }

    @Test void theCanvasDrawsTheHierarchyAndTheStepperStepsThroughItsBoxes() {
        window.comboBox("builder").selectItem("bvh");
        Expected e = Expected.of(GuiActionRunner.execute(() -> bench.model().scene()));
        assertThat(GuiActionRunner.execute(() -> bench.model().built() instanceof BvhView)).isTrue();
        window.label("stat.nodes").requireText(Integer.toString(e.bvh().nodeCount()));
        window.label("stat.depth").requireText(Integer.toString(e.bvh().maxDepth()));
        window.label("stat.memory").requireText(StatsPanel.memory(e.bvh().memoryBytes()));
        for (String offered : new String[] {"bvhWidth", "bins", "leafSize", "kmaxdepth", "kt", "ki"})
            assertThat(showing(offered)).as("%s is offered for the hierarchy", offered).isTrue();
        for (String other : new String[] {"lambda", "planeSearch", "referenceBudget", "perfectSplits"})
            assertThat(showing(other)).as("%s is a kd-tree's setting", other).isFalse();
        window.label("autoDepth").requireText("-1 = auto: depth cap 64");
        assertThat(window.tree("kdtree").target().getModel().getRoot().toString()).startsWith("#0  box [");

        assertThat(window.label("step.result").text()).as("the ray's cost, as the library counts it").endsWith(String.format(
                Locale.ROOT, "(%d nodes, %d leaves, %d box tests, %d tests)", e.ray().nodes, e.ray().leaves, e.ray().boxTests,
                e.ray().primitiveTests));
        window.button("step.next").click();
        assertThat(window.label("step.label").text()).startsWith("step 2 /").endsWith("interior box: test its children's boxes");
        assertThat(window.label("step.node").text()).startsWith("node #0 (box of children #1 and #2)");
        window.button("step.next").click();
        assertThat(window.label("step.label").text()).endsWith("test a child's box");
        assertThat(window.label("step.children").text()).startsWith("box #1 ");
        window.button("step.last").click();
        assertThat(window.label("step.label").text()).endsWith("done");

        window.tabbedPane("steppers").selectTab("Nearest neighbours");
        window.label("knn.label").requireText(NearestStepperPanel.KD_TREES_ONLY);
        window.comboBox("builder").selectItem("sah");
        assertThat(GuiActionRunner.execute(() -> bench.model().tree())).isNotNull();
        assertThat(showing("lambda")).isTrue();
    }

    @Test void theCollisionsSayTheyNeedAKdTree() {
        window.comboBox("builder").selectItem("bvh");
        window.tabbedPane("tabs").selectTab("Collisions");
        window.label("collide.frame").requireText(CollisionsView.KD_TREES_ONLY);
        window.button("collide.start").click();
        window.button("collide.start").requireText("Start");
        assertThat(GuiActionRunner.execute(() -> bench.collisions().running())).isFalse();
        GuiActionRunner.execute(() -> bench.model().setSettings(bench.model().settings().forBuilder("sah")));
        window.label("collide.frame").requireText("frame 0");
        window.button("collide.step").click();
        window.label("collide.frame").requireText("frame 1");
    }

    private boolean showing(String name) {
        return !window.robot().finder().findAll(bench, c -> name.equals(c.getName()) && c.isShowing()).isEmpty();
    }
}
