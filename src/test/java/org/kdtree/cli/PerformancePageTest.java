package org.kdtree.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * Issue 46, item 4: docs/performance.md opens with today's figures and how each was measured, in
 * about a page, and keeps its history as one dated log at the end, not as a diary of sections.
 */
class PerformancePageTest {
    @Test void todaysFiguresComeFirstWithTheirCommandsAndTheHistoryLast() throws IOException {
        List<String> lines = Files.readAllLines(Path.of("docs/performance.md"));
        List<String> headings = lines.stream().filter(l -> l.startsWith("## ")).toList();
        assertThat(headings.get(0)).isEqualTo("## Today's figures");
        assertThat(headings.get(headings.size() - 1)).isEqualTo("## History");
        assertThat(headings).noneMatch(h -> h.matches("## \\d.*"));
        int commands = lines.indexOf("### The commands");
        assertThat(commands).as("the commands of the figures within the first page").isBetween(1, 70);
        String firstPage = String.join("\n", lines.subList(0, commands));
        assertThat(firstPage).contains("Embree", "Sunflow", "2026-", "| P, camera rays", "render");
        assertThat(lines).hasSizeLessThan(250);
    }
}
