package org.kdtree.render;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import org.junit.jupiter.api.Test;

/** The render command's bar, as a terminal shows it: redrawn in place, never backwards, ended by a new line. */
class ProgressBarTest {
    @Test void redrawsInPlaceNeverBackwardsAndEndsTheLine() {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        ProgressBar bar = new ProgressBar(new PrintStream(bytes, true), 4);
        bar.update(1);
        bar.update(3);
        bar.update(2);   // a thread reporting late
        bar.update(4);
        String out = bytes.toString();
        assertThat(out).startsWith("\r[").contains("25% (1/4 tiles)", "75% (3/4 tiles)").doesNotContain("50%")
                .endsWith("100% (4/4 tiles)" + System.lineSeparator());
    }
}
