package org.kdtree.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class StatsCommandTest {
    @TempDir Path dir;

    private record Run(int code, String out, String err) {
    }

    private static Run run(String... args) {
        PrintStream oldOut = System.out, oldErr = System.err;
        ByteArrayOutputStream out = new ByteArrayOutputStream(), err = new ByteArrayOutputStream();
        try {
            System.setOut(new PrintStream(out, true));
            System.setErr(new PrintStream(err, true));
            int code = Main.run(args);
            return new Run(code, out.toString(), err.toString());
        } finally {
            System.setOut(oldOut);
            System.setErr(oldErr);
        }
    }

    @Test void printsStatisticsForEveryBuilderOnTheBundledScenes() {
        for (String b : new String[] {"sah", "median-plane", "object-median", "centre-midpoint"}) {
            Run r = run("stats", "scenes/talk-figures.scene2d", "--builder", b);
            assertThat(r.code()).as(r.err()).isZero();
            assertThat(r.out()).contains("builder: " + b).contains("nodes: ").contains("expected cost: ").contains("build time: ");
        }
        Run r = run("stats", "scenes/clustered-spheres.obj", "--lambda", "0.5", "--max-depth", "12");
        assertThat(r.code()).as(r.err()).isZero();
        assertThat(r.out()).contains("lambda=0.5").contains("maxDepth=12");
    }

    @Test void aMalformedFileGivesOneClearLineAndNoStackTrace() throws Exception {
        Path bad = dir.resolve("bad.obj");
        Files.writeString(bad, "v 0 0 0\nv 1 0 0\nf 1 2 x\n");
        Run r = run("stats", bad.toString());
        assertThat(r.code()).isEqualTo(2);
        assertThat(r.err().strip()).isEqualTo("error: " + bad + ":3: 'x' is not a vertex index");
    }

    @Test void unknownBuildersAndMisplacedOptionsAreExplained() {
        Run r = run("stats", "scenes/talk-figures.scene2d", "--builder", "bvh");
        assertThat(r.code()).isEqualTo(2);
        assertThat(r.err()).contains("unknown builder 'bvh'").doesNotContain("Exception");
        r = run("stats", "scenes/talk-figures.scene2d", "--builder", "median-plane", "--lambda", "0.5");
        assertThat(r.err()).contains("--lambda and --algorithm apply to the sah builder only");
    }
}
