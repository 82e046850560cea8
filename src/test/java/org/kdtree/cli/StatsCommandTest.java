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

    @Test void aMalformedFileGivesOneClearLineAndNoStackTrace() throws Exception {
        Path bad = dir.resolve("bad.obj");
        Files.writeString(bad, "v 0 0 0\nv 1 0 0\nf 1 2 x\n");
        CliRun r = run("stats", bad.toString());
        assertThat(r.code()).isEqualTo(2);
        assertThat(r.err().strip()).isEqualTo("error: " + bad + ":3: 'x' is not a vertex index");
    }

    @Test void unknownBuildersAndMisplacedOptionsAreExplained() {
        CliRun r = run("stats", "scenes/talk-figures.scene2d", "--builder", "bvh");
        assertThat(r.code()).isEqualTo(2);
        assertThat(r.err()).contains("unknown builder 'bvh'").doesNotContain("Exception");
        r = run("stats", "scenes/talk-figures.scene2d", "--builder", "median-plane", "--lambda", "0.5");
        assertThat(r.err()).contains("--lambda and --algorithm apply to the sah builder only");
    }

    @Test void gridRepeatsAMeshAndRefusesA2DScene() {
        CliRun r = run("stats", "scenes/clustered-spheres.obj", "--grid", "2");
        assertThat(r.code()).as(r.err()).isZero();
        assertThat(r.out()).contains("(41480 primitives, 3-D)");
        r = run("stats", "scenes/talk-figures.scene2d", "--grid", "2");
        assertThat(r.code()).isEqualTo(2);
        assertThat(r.err()).contains("--grid applies to OBJ meshes only");
    }
}
