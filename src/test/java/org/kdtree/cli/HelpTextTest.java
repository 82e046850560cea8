package org.kdtree.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.kdtree.render.RenderJob;

/** What a newcomer reads first: every command's help, whole and unbroken, and counts in good English. */
class HelpTextTest {
    private static final List<String> COMMANDS = List.of("gui", "stats", "raycast", "render", "tradeoff", "knn", "knn-study", "grade");

    @Test void everyCommandsHelpFitsAnEightyColumnTerminalAndEndsWell() {
        for (String c : COMMANDS) {
            CliRun r = CliRun.of(c, "--help");
            assertThat(r.code()).as(c).isZero();
            assertThat(r.out()).as(c).startsWith("Usage: kdtree " + c);
            for (String line : r.out().split("\\R"))
                assertThat(line.length()).as("%s --help: %s", c, line).isLessThanOrEqualTo(80);
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

    @Test void countsAreSingularForOne() {
        assertThat(RenderJob.count(1, "light")).isEqualTo("1 light");
        assertThat(RenderJob.count(2, "light")).isEqualTo("2 lights");
        assertThat(RenderJob.count(10_370, "primitive")).isEqualTo("10,370 primitives");
    }
}
