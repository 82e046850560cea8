package org.kdtree.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.junit.jupiter.api.Test;

/** What a newcomer reads first: every command's help, whole and unbroken. */
class HelpTextTest {
    private static final List<String> COMMANDS = List.of("gui", "stats", "raycast", "render", "tradeoff", "knn", "knn-study", "grade",
            "grade-class");

    @Test void everyCommandsHelpFitsAnEightyColumnTerminalAndEndsWell() {
        for (String c : COMMANDS) {
            CliRun r = CliRun.of(c, "--help");
            assertThat(r.code()).as(c).isZero();
            assertThat(r.out()).as(c).startsWith("Usage: kdtree " + c);
            for (String line : r.out().split("\\R"))
                assertThat(line.length()).as("%s --help: %s", c, line).isLessThanOrEqualTo(80);
            assertThat(r.out()).as("%s --help: a number broken across lines (\"1..\" then \"65536\")", c)
                    .doesNotContainPattern("\\d\\.*\\R\\s*\\d");
        }
    }

    @Test void raycastsHelpShowsTheLineItPrints() {
        assertThat(CliRun.of("raycast", "--help").out())
                .contains("The benchmark prints one line:", "system mesh tris build_ms nodes leaves depth",
                        "P_hits P_tsum P_mrays R_hits R_tsum R_mrays");
    }

    @Test void theTopLevelHelpListsEveryCommand() {
        CliRun r = CliRun.of("--help");
        assertThat(r.code()).isZero();
        for (String c : COMMANDS) assertThat(r.out()).contains(c);
    }

    @Test void theTopLevelHelpsSummariesAreWholeSentences() {
        String out = CliRun.of("--help").out();
        String list = out.substring(out.indexOf("Commands:\n") + "Commands:\n".length(), out.indexOf("\nExit codes:"));
        for (String entry : list.strip().split("\\R(?=  \\S)")) {   // a command's entry: its name's line and the indented rest
            String summary = entry.strip().replaceAll("\\s+", " ");
            assertThat(summary).as("the command list's summary is cut: %s", summary).endsWith(".");
        }
        for (String line : out.substring(out.indexOf("Exit codes:")).strip().split("\\R"))
            assertThat(line).as("the exit codes' lines end at a clause, or continue indented: %s", line).matches("(?s).*[;.]|.*\\($|.*impossible");
    }

    @Test void raycastsHelpShowsVerify() {
        assertThat(CliRun.of("raycast", "--help").out()).contains("--verify=STRIDE", "brute force");
        assertThat(CliRun.of("raycast", "--help").out()).as("how to turn the vector path on").contains("--add-modules jdk.incubator.vector");
    }

    @Test void theAlgorithmsHelpSaysBinnedBuildsAnotherTree() {
        String help = CliRun.of("stats", "--help").out().replaceAll("\\s+", " ");
        assertThat(help).contains("NAIVE, SORTED and EVENT build the same tree in different times; BINNED builds another")
                .doesNotContain("(same tree, different time)");
    }

    /** Issue 34, item 12: the help texts a newcomer reads, each as it should be. */
    @Test void theHelpTextsSayWhatAppliesInOneNotation() {
        for (String c : COMMANDS) {
            String help = CliRun.of(c, "--help").out();
            String flat = help.replaceAll("\\s+", " ");
            assertThat(help).as("%s: placeholders are N, X, FILE, NAME, not <name>", c).doesNotContainPattern("=<\\w+>");
            assertThat(flat).as("%s: ranges are written 'a to b'", c).doesNotContainPattern("\\d\\.\\.\\d");
            assertThat(flat).as("%s: which deadline default applies", c).doesNotContain("default: 60, grade: 10");
            assertThat(flat).as(c).doesNotContain("leaves below 1 references");
            assertThat(CliRun.of(c, "-q", "--help").code()).as("%s takes -q", c).isZero();
        }
        for (String c : List.of("knn", "knn-study", "grade")) {
            String help = CliRun.of(c, "--help").out();
            assertThat(help).as("%s needs a kd-tree: no bvh offered", c).doesNotContain("--bvh-width").doesNotContain(", or bvh");
        }
        assertThat(CliRun.of("stats", "--help").out()).contains("--bvh-width");
        assertThat(CliRun.of("raycast", "--help").out().replaceAll("\\s+", " ")).contains("threads: threads building the tree and tracing each ray set");
        assertThat(CliRun.of("stats", "--help").out().replaceAll("\\s+", " "))
                .contains("exact (exact, no leaf without a plane search)")
                .contains("(default: 60 s; grade and grade-class: 10 s; 0.1 to 3600)");
        CliRun unknown = CliRun.of("stats", "scenes:talk-figures", "-b", "nosuch");
        assertThat(unknown.err().strip()).startsWith("error: unknown builder 'nosuch' (known: sah, ").endsWith(", bvh)");
    }

    /**
     * The mixins whose options are made in code (builder settings, --grid, the studies' --csv and
     * --chart) each give their options to a command that has several of them: picocli keeps one
     * model transformer per command, and that one must add them all.
     */
    @Test void aCommandShowsTheOptionsOfEveryMixinMadeInCode() {
        for (String c : List.of("stats", "raycast", "tradeoff"))
            assertThat(CliRun.of(c, "--help").out()).as(c).contains("-b, --builder=NAME", "--lambda=X", "--grid=N");
        for (String c : List.of("tradeoff", "knn-study"))
            assertThat(CliRun.of(c, "--help").out()).as(c).contains("-b, --builder=NAME", "--csv=FILE", "--chart=FILE",
                    "(default: " + c + "-");
    }

    @Test void theVersionIsThePoms() throws Exception {
        String pom = java.nio.file.Files.readString(java.nio.file.Path.of("pom.xml"));
        String version = pom.replaceFirst("(?s).*?<artifactId>kdtree</artifactId>\\s*<version>([^<]+)</version>.*", "$1");
        assertThat(version).isEqualTo("0.1.0-SNAPSHOT");
        assertThat(CliRun.of("--version").out().strip()).isEqualTo("kdtree " + version);
        assertThat(CliRun.of("raycast", "--version").out().strip()).isEqualTo("kdtree " + version);
    }

    @Test void theReadmesOptionListNamesEverySetting() throws Exception {
        String readme = java.nio.file.Files.readString(java.nio.file.Path.of("README.md"));
        for (org.kdtree.accel.Setting<?> s : org.kdtree.spec.BuilderSpec.allSettingRows()) assertThat(readme).as(s.option()).contains("`" + s.option());
    }
}
