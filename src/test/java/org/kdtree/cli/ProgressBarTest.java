package org.kdtree.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import org.junit.jupiter.api.Test;

/**
 * The bar as a terminal shows it: redrawn in place, never backwards, lines printed above it, cleared
 * at the end; in a log, plain lines on a clock and no redraws (issue 46, item 6).
 */
class ProgressBarTest {
    @Test void redrawsInPlaceNeverBackwardsAndClearsItsLine() {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (ProgressBar bar = new ProgressBar(new PrintStream(bytes, true), 4, "tiles")) {
            bar.update(1);
            bar.update(3);
            bar.update(2);   // a thread reporting late
            bar.update(4);
        }
        String out = bytes.toString();
        assertThat(out).startsWith("\r[").contains(" 25% (1/4 tiles)", " 75% (3/4 tiles)").doesNotContain(" 50%")
                .contains("100% (4/4 tiles)").endsWith("\r\033[K");
    }

    @Test void stepsNameTheWorkAndResultsPrintAboveTheBar() {
        ByteArrayOutputStream bar = new ByteArrayOutputStream(), results = new ByteArrayOutputStream();
        PrintStream res = new PrintStream(results, true);
        try (ProgressBar p = new ProgressBar(new PrintStream(bar, true), 3, "steps")) {
            p.step(0, "build 1 of 2");
            p.print(res, "first result");
            p.step(1, "build 2 of 2");
        }
        assertThat(bar.toString()).contains("(0/3 steps) build 1 of 2", "(1/3 steps) build 2 of 2");
        assertThat(results.toString()).isEqualTo("first result" + System.lineSeparator());
    }

    @Test void inALogItWritesPlainLinesOnAClockAndNoRedraws() throws InterruptedException {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (ProgressBar p = new ProgressBar(new PrintStream(bytes, true), 8, "steps", true, 40)) {
            p.step(3, "P rays (warm-up)");
            long until = System.nanoTime() + 5_000_000_000L;
            while (!bytes.toString().contains("\n") && System.nanoTime() < until) Thread.sleep(20);
        }
        String log = bytes.toString();
        assertThat(log).doesNotContain("\r", "\033", "#").containsPattern("(?m)^progress: \\d+ s, 3 of 8 steps, P rays \\(warm-up\\)$");
    }

    @Test void aCommandOutsideATerminalLogsUnlessQuiet() {
        assertThat(ProgressBar.onTerminal()).as("the tests run with no terminal, on every JDK").isFalse();
        try (ProgressBar logged = ProgressBar.forCommand(false, 1, "steps"); ProgressBar quiet = ProgressBar.forCommand(true, 1, "steps")) {
            assertThat(logged.writesLogLines()).isTrue();
            assertThat(quiet.writesLogLines()).isFalse();
        }
    }
}
