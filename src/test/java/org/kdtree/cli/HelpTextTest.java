package org.kdtree.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.junit.jupiter.api.Test;

/** What a newcomer reads first: every command's help, whole and unbroken. */
class HelpTextTest {
    private static final List<String> COMMANDS = List.of("gui", "stats", "raycast", "render", "tradeoff", "knn", "knn-study", "grade");

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
    }

    @Test void theAlgorithmsHelpSaysBinnedBuildsAnotherTree() {
        String help = CliRun.of("stats", "--help").out().replaceAll("\\s+", " ");
        assertThat(help).contains("NAIVE, SORTED and EVENT build the same tree in different times; BINNED builds another")
                .doesNotContain("(same tree, different time)");
    }
}
