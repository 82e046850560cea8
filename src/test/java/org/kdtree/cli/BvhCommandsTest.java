package org.kdtree.cli;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code -b bvh} wherever a builder is chosen: the commands that answer ray queries build a
 * bounding volume hierarchy with its own settings, validated like any other; the commands that
 * need a kd-tree refuse it in one line.
 */
class BvhCommandsTest {
    @TempDir Path dir;

    @Test void statsDescribesTheHierarchyOfA2DSceneAMeshAndAJsonScene() {
        for (String scene : new String[] {"scenes/talk-figures.scene2d", "scenes/clustered-spheres.obj", "scenes:cornell-box"}) {
            CliRun r = CliRun.of("stats", scene, "-b", "bvh");
            assertThat(r.code()).as(r.err()).isZero();
            assertThat(r.out()).as(scene).contains("builder: bvh (width=4 bins=32 leafSize=16")
                    .contains("nodes: ", "leaves: ", "max depth: ", "references: ", "memory: ", "expected cost: ", "build time: ");
        }
        CliRun r = CliRun.of("stats", "scenes/clustered-spheres.obj", "-b", "bvh", "--bvh-width", "8", "--bins", "8",
                "--leaf-size", "1", "--max-depth", "12");
        assertThat(r.code()).as(r.err()).isZero();
        assertThat(r.out()).contains("builder: bvh (width=8 bins=8 leafSize=1 maxDepth=12").contains("max depth: 12");
        assertThat(references(r.out())).as("a BVH holds each triangle once").isEqualTo(10_370);
    }

    /** The benchmark line of docs/raycast.md, system kdtree-bvh, with the kd-tree's hit counts and distance sums. */
    @Test void raycastPrintsTheBenchmarkLineOfTheBvh() {
        String[] sah = line(CliRun.of("raycast", "scenes/meshes/mtl-demo.obj", "--runs", "1", "--warmup", "0"));
        String[] bvh = line(CliRun.of("raycast", "scenes/meshes/mtl-demo.obj", "--runs", "1", "--warmup", "0", "-b", "bvh",
                "--bvh-width", "8", "--threads", "2"));
        assertThat(bvh[0]).isEqualTo("kdtree-bvh");
        assertThat(bvh[1]).isEqualTo("mtl-demo");
        for (int f : new int[] {7, 10}) assertThat(bvh[f]).as("hits").isEqualTo(sah[f]);
        for (int f : new int[] {8, 11})
            assertThat(Double.parseDouble(bvh[f])).as("t sum").isCloseTo(Double.parseDouble(sah[f]), within(1e-9 * Double.parseDouble(sah[f])));
        assertThat(Long.parseLong(sah[10])).as("a workload that hits").isPositive();
    }

    private static String[] line(CliRun r) {
        assertThat(r.code()).as(r.err()).isZero();
        String[] f = r.out().strip().split(" ");
        assertThat(f).hasSize(13);
        return f;
    }

    @Test void theBvhsSettingsAreCheckedAndTheKdTreesRefused() {
        assertOneLine(CliRun.of("stats", "scenes/talk-figures.scene2d", "-b", "bvh", "--bvh-width", "9"),
                "--bvh-width must be between 2 and 8, got 9");
        assertOneLine(CliRun.of("stats", "scenes/talk-figures.scene2d", "-b", "bvh", "--lambda", "0.5"),
                "--lambda applies to the sah builder only, not to bvh");
        assertOneLine(CliRun.of("stats", "scenes/talk-figures.scene2d", "--bvh-width", "2"),
                "--bvh-width applies to the bvh builder only, not to sah");
        assertOneLine(CliRun.of("render", "scenes/diffuse-only.json", "-o", dir.resolve("x.png").toString(), "-b", "bvh",
                "--no-perfect-splits"), "--no-perfect-splits applies to the kd-tree builders only, not to bvh");
    }

    /** Jittered samples (--spp 2), so that no ray meets the room's edges exactly, where either of two triangles is right. */
    @Test void renderWithTheBvhWritesTheSamePictureAsWithTheSah() throws Exception {
        Path sah = dir.resolve("sah.png"), bvh = dir.resolve("bvh.png");
        CliRun a = CliRun.of("render", "scenes:cornell-box", "-o", sah.toString(), "--spp", "2", "--width", "24", "--height", "18", "-q");
        CliRun b = CliRun.of("render", "scenes:cornell-box", "-o", bvh.toString(), "--spp", "2", "--width", "24", "--height", "18", "-q",
                "-b", "bvh", "--bvh-width", "2");
        assertThat(a.code()).as(a.err()).isZero();
        assertThat(b.code()).as(b.err()).isZero();
        assertThat(b.out()).contains("build time: ").contains("(bvh)").contains("bvh:").contains("nodes: ").contains("wrote " + bvh);
        BufferedImage x = ImageIO.read(sah.toFile()), y = ImageIO.read(bvh.toFile());
        for (int j = 0; j < x.getHeight(); j++)
            for (int i = 0; i < x.getWidth(); i++)
                assertThat(y.getRGB(i, j)).as("pixel %d,%d", i, j).isEqualTo(x.getRGB(i, j));
    }

    @Test void theCommandsThatNeedAKdTreeRefuseTheBvhInOneLine() throws Exception {
        Path points = Files.writeString(dir.resolve("p.csv"), "0,0\n1,0\n0,1\n");
        String out = dir.resolve("o.csv").toString();
        List<CliRun> runs = List.of(
                CliRun.of("knn", points.toString(), "--queries", points.toString(), "--k", "1", "--out", out, "-b", "bvh"),
                CliRun.of("knn-study", "--generate", "uniform", "--n", "50", "--k", "1", "--csv", out, "-b", "bvh"),
                CliRun.of("grade", "-b", "bvh"));
        for (CliRun r : runs)
            assertOneLine(r, "-b bvh builds a bounding volume hierarchy, which answers ray queries only (raycast, stats, render, "
                    + "tradeoff, the workbench); this needs a kd-tree builder: sah, median-plane");
        assertThat(dir.resolve("o.csv")).as("refused before any output").doesNotExist();
    }

    @Test void theRayCommandsHelpNamesTheBvhAndItsWidthTheOthersDoNot() {
        for (String c : new String[] {"stats", "raycast", "render", "tradeoff"}) {
            String help = CliRun.of(c, "--help").out().replaceAll("\\s+", " ");
            assertThat(help).as(c).contains("or bvh (a bounding volume hierarchy: ray queries and the workbench)")
                    .contains("--bvh-width=N BVH width: children per node");
        }
        for (String c : new String[] {"knn", "knn-study", "grade"}) {   // issue 34, item 12: they refuse it, so they do not offer it
            String help = CliRun.of(c, "--help").out().replaceAll("\\s+", " ");
            assertThat(help).as(c).contains("(a kd-tree builder: this command does not take bvh)").doesNotContain("--bvh-width");
        }
    }

    private static void assertOneLine(CliRun r, String message) {
        assertThat(r.code()).as(r.err()).isEqualTo(2);
        assertThat(r.err().strip()).startsWith("error: " + message).doesNotContain("\n").doesNotContain("Exception");
    }

    private static long references(String statsOutput) {
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("references: (\\d+)").matcher(statsOutput);
        assertThat(m.find()).as(statsOutput).isTrue();
        return Long.parseLong(m.group(1));
    }
}
