package org.kdtree.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class StatsCommandTest {
    @TempDir Path dir;

    private static CliRun run(String... args) {
        return CliRun.of(args);
    }

    @Test void printsStatisticsForEveryBuilderOnTheBundledScenes() {
        for (String b : new String[] {"sah", "median-plane", "object-median", "centre-midpoint"}) {
            CliRun r = run("stats", "scenes/talk-figures.scene2d", "--builder", b);
            assertThat(r.code()).as(r.err()).isZero();
            assertThat(r.out()).contains("builder: " + b).contains("nodes: ").contains("expected cost: ").contains("build time: ");
        }
        CliRun r = run("stats", "scenes/clustered-spheres.obj", "--lambda", "0.5", "--max-depth", "12");
        assertThat(r.code()).as(r.err()).isZero();
        assertThat(r.out()).contains("lambda=0.5").contains("maxDepth=12");
    }

    @Test void readsJsonScenesAndBundledScenesByName() {
        CliRun r = CliRun.of("stats", "scenes:cornell-box", "-b", "median-plane");
        assertThat(r.code()).as(r.err()).isZero();
        assertThat(r.out()).contains("scene: scenes:cornell-box (4,440 primitives, 3-D)").contains("builder: median-plane");
        assertThat(CliRun.of("stats", "scenes:nope").err()).startsWith("error: scenes:nope: no bundled scene of that name");
    }

    @Test void aMalformedFileGivesOneClearLineAndNoStackTrace() throws Exception {
        Path bad = dir.resolve("bad.obj");
        Files.writeString(bad, "v 0 0 0\nv 1 0 0\nf 1 2 x\n");
        CliRun r = run("stats", bad.toString());
        assertThat(r.code()).isEqualTo(2);
        assertThat(r.err().strip()).isEqualTo("error: " + bad + ":3: 'x' is not a vertex index");
    }

    @Test void unknownBuildersAndMisplacedOptionsAreExplained() {
        CliRun r = run("stats", "scenes/talk-figures.scene2d", "--builder", "octree");
        assertThat(r.code()).isEqualTo(2);
        assertThat(r.err()).contains("unknown builder 'octree'").doesNotContain("Exception");
        r = run("stats", "scenes/talk-figures.scene2d", "--builder", "median-plane", "--lambda", "0.5");
        assertThat(r.err()).contains("--lambda applies to the sah builder only, not to median-plane");
    }

    @Test void qualityPresetsBuildSmallerTreesAndAnExplicitDepthWins() {
        CliRun exact = run("stats", "scenes/clustered-spheres.obj", "--runs", "1", "--warmup", "0");
        CliRun fast = run("stats", "scenes/clustered-spheres.obj", "--quality", "fast", "--runs", "1", "--warmup", "0");
        assertThat(fast.code()).as(fast.err()).isZero();
        assertThat(fast.out()).contains("algorithm=event", "leafBelow=11");
        assertThat(nodes(fast.out())).isLessThan(nodes(exact.out()));
        CliRun capped = run("stats", "scenes/clustered-spheres.obj", "--quality", "fast", "--max-depth", "5", "--runs", "1", "--warmup", "0");
        assertThat(capped.out()).contains("maxDepth=5", "max depth: 5");
        CliRun bad = run("stats", "scenes/clustered-spheres.obj", "--quality", "fastest");
        assertThat(bad.code()).isEqualTo(2);
        assertThat(bad.err()).contains("--quality").contains("FAST").doesNotContain("Exception");
    }

    private static int nodes(String statsOutput) {
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("nodes: (\\d+)").matcher(statsOutput);
        assertThat(m.find()).as(statsOutput).isTrue();
        return Integer.parseInt(m.group(1));
    }

    @Test void gridRepeatsAMeshAndRefusesA2DScene() {
        CliRun r = run("stats", "scenes/clustered-spheres.obj", "--grid", "2");
        assertThat(r.code()).as(r.err()).isZero();
        assertThat(r.out()).contains("(41,480 primitives, 3-D)");
        r = run("stats", "scenes/talk-figures.scene2d", "--grid", "2");
        assertThat(r.code()).isEqualTo(2);
        assertThat(r.err()).contains("--grid applies to OBJ meshes only");
    }
}
