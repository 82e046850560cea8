package org.kdtree.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;

/** Whatever goes wrong, the command line prints one line, never a stack trace. */
class FailureTest {
    @Test void anUnexpectedFailureIsOneLineWithTheFullReportInAFile() throws Exception {
        StringWriter err = new StringWriter();
        int code = Failure.report(new IllegalStateException("tree exceeds 67108863 nodes"), new PrintWriter(err, true));
        assertThat(code).isEqualTo(Failure.INTERNAL);
        String line = err.toString().strip();
        assertThat(line).doesNotContain("\n").startsWith("error: unexpected IllegalStateException: tree exceeds 67108863 nodes");
        Matcher m = Pattern.compile("report is in (\\S+)\\)").matcher(line);
        assertThat(m.find()).as(line).isTrue();
        Path report = Path.of(m.group(1));
        assertThat(Files.readString(report)).contains("IllegalStateException", "at org.kdtree.cli.FailureTest");
        Files.delete(report);
    }

    @Test void anEmptyMeshIsRefusedBeforeAnyRayIsTraced(@org.junit.jupiter.api.io.TempDir Path dir) throws Exception {
        Path empty = Files.writeString(dir.resolve("empty.obj"), "# no faces\nv 0 0 0\n");
        for (String command : new String[] {"raycast", "tradeoff"}) {
            CliRun r = CliRun.of(command, empty.toString());
            assertThat(r.code()).isEqualTo(2);
            assertThat(r.err().strip()).isEqualTo("error: " + empty + ": no triangles (no 'f' lines): not an OBJ mesh, or an empty one");
        }
    }

    @Test void aBadOptionIsOneLineWithWhereToReadMore() {
        CliRun r = CliRun.of("stats", "scenes/clustered-spheres.obj", "--quality", "fastest");
        assertThat(r.code()).isEqualTo(2);
        assertThat(r.err().strip()).isEqualTo("error: Invalid value for option '--quality': expected one of [FAST, BALANCED, EXACT]"
                + " (case-insensitive) but was 'fastest' (kdtree stats --help)");
        assertThat(CliRun.of("render", "--nope", "x.json").err().strip()).isEqualTo("error: Unknown option: '--nope' (kdtree render --help)");
    }

    @Test void anUnknownCommandIsAnErrorEvenWithHelp() {
        CliRun r = CliRun.of("nearest", "--help");
        assertThat(r.code()).isEqualTo(2);
        assertThat(r.err().strip()).isEqualTo("error: unknown command 'nearest'; the commands are gui, stats, raycast, render, tradeoff, knn, knn-study, compare-trees, similar, grade, grade-class (kdtree --help)");
    }

    @Test void countsAgreeWithTheirNouns() {
        assertThat(org.kdtree.render.RenderJob.count(1, "light")).isEqualTo("1 light");
        assertThat(org.kdtree.render.RenderJob.count(0, "light")).isEqualTo("0 lights");
        assertThat(org.kdtree.render.RenderJob.count(69451, "triangle")).isEqualTo("69,451 triangles");
        CliRun r = CliRun.of("stats", "scenes/talk-figures.scene2d");
        assertThat(r.out()).contains("primitives, 2-D)").doesNotContain("1 primitives");
    }

    @Test void noDisplayIsAUserLineNotABug() {
        StringWriter err = new StringWriter();
        assertThat(Failure.report(new java.awt.AWTError("Can't connect to X11 window server using ':99'"), new PrintWriter(err, true)))
                .isEqualTo(Failure.USAGE);
        assertThat(err.toString()).startsWith("error: cannot open a window").contains("need no display").doesNotContain("bug");
    }

    @Test void runningOutOfMemorySaysHowToGiveJavaMore() {
        StringWriter err = new StringWriter();
        assertThat(Failure.report(new OutOfMemoryError("Java heap space"), new PrintWriter(err, true))).isEqualTo(Failure.MEMORY);
        assertThat(err.toString()).startsWith("error: out of memory (Java may use ").contains("-Xmx");
    }

    @Test void renderAndStatsOptionsOutOfRangeAreOneLine() {
        String[][] cases = {
                {"render", "scenes/cornell-box.json", "--width", "100000", "-o", "x.png"}, {"--width must be between 1 and 16384, got 100000"},
                {"render", "scenes/cornell-box.json", "--spp", "1000000000", "-o", "x.png"}, {"--spp must be between 1 and 4096"},
                {"render", "scenes/cornell-box.json", "--ray-depth", "5000", "-o", "x.png"}, {"--ray-depth must be between 0 and 64"},
                {"render", "scenes/cornell-box.json", "-o", "scenes"}, {"-o scenes: is a folder"},
                {"render", "scenes/cornell-box.json", "-o", "x.jpg"}, {"give a file name ending in .png"},
                {"render", "scenes/cornell-box.json", "-o", "no-such-folder/x.png"}, {"does not exist"},
                {"stats", "scenes/clustered-spheres.obj", "--grid", "1000"}, {"--grid must be between 1 and 64, got 1000"},
                {"stats", "scenes/clustered-spheres.obj", "--reference-budget", "0"}, {"--reference-budget must be between 1 and 65536, got 0"},
                {"stats", "scenes/clustered-spheres.obj", "--runs", "0"}, {"--runs must be between 1 and 1000, got 0"},
                {"tradeoff", "scenes/talk-figures.scene2d"}, {"give an OBJ file"},
                {"raycast", "scenes/talk-figures.scene2d"}, {"give an OBJ file"},
                {"tradeoff", "scenes/clustered-spheres.obj", "--chart-rpt", "-5"}, {"--chart-rpt must be between 0.001 and 1000000, got -5"},
                {"stats", "scenes/clustered-spheres.obj", "--warmup", "-1"}, {"--warmup must be between 0 and 1000, got -1"},
                {"stats", "scenes/clustered-spheres.obj", "--max-depth", "1000"},
                {"--max-depth must be between -1 and 64 (-1 = auto: 8 + 1.3 log2 N for a kd-tree, 64 for a BVH), got 1000"},
                {"stats", "scenes/clustered-spheres.obj", "--kt", "-1"}, {"--kt must be between 0 and 10000, got -1"},
                {"stats", "scenes/clustered-spheres.obj", "--lambda", "0"}, {"--lambda must be between 0.01 and 1, got 0"},
                {"raycast", "scenes/clustered-spheres.obj", "--threads", "100000"}, {"--threads must be between 1 and 256, got 100000"},
                {"tradeoff", "scenes/clustered-spheres.obj", "--csv", "no-such-folder/t.csv"}, {"--csv no-such-folder/t.csv: the folder"},
                {"raycast", "scenes/clustered-spheres.obj", "--rays", "scenes/clustered-spheres.obj", "--hits", "no-such-folder/h.txt"},
                {"the folder"},
        };
        for (int i = 0; i < cases.length; i += 2) {
            CliRun r = CliRun.of(cases[i]);
            assertThat(r.code()).as(String.join(" ", cases[i])).isEqualTo(2);
            assertThat(r.err().strip()).as(String.join(" ", cases[i])).startsWith("error: ").contains(cases[i + 1][0])
                    .doesNotContain("\n").doesNotContain("Exception");
        }
    }
}
