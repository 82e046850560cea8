package org.kdtree.gui;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.kdtree.limits.Limit;

class WorkbenchLimitsTest {
    @Test void eachLimitAllowsItsEndsAndRejectsJustBeyondThem() {
        assertThat(WorkbenchLimits.STEPPER_K.check("k", 64)).isEqualTo(64);
        assertThatThrownBy(() -> WorkbenchLimits.STEPPER_K.check("k", 65)).isInstanceOf(IllegalArgumentException.class);
        assertThatThrownBy(() -> WorkbenchLimits.BALLS.check("balls", 0)).isInstanceOf(IllegalArgumentException.class);
        assertThat(WorkbenchLimits.PREVIEW_WIDTH.check("width", 16)).isEqualTo(16);
    }

    /** docs/limits.md lists the workbench's ranges too: it must say what the workbench enforces. */
    @Test void docsListEveryWorkbenchLimitWithItsRange() throws Exception {
        List<String> rows = Files.readAllLines(Path.of("docs/limits.md")).stream().filter(r -> r.startsWith("| ")).toList();
        for (Limit l : WorkbenchLimits.ALL) {
            String expected = "| " + l.title() + " | " + l.range() + " |";
            assertThat(rows).as("a row of docs/limits.md starting " + expected).anyMatch(r -> r.startsWith(expected));
        }
    }
}
