package org.kdtree.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import org.junit.jupiter.api.Test;

/** Without a display (the unit tests run headless), no command prints usage, and {@code gui} says why it cannot open. */
class GuiCommandTest {
    private static String[] run(int[] code, String... args) {
        PrintStream oldOut = System.out, oldErr = System.err;
        ByteArrayOutputStream out = new ByteArrayOutputStream(), err = new ByteArrayOutputStream();
        try {
            System.setOut(new PrintStream(out, true));
            System.setErr(new PrintStream(err, true));
            code[0] = Main.run(args);
            return new String[] {out.toString(), err.toString()};
        } finally {
            System.setOut(oldOut);
            System.setErr(oldErr);
        }
    }

    @Test void withoutADisplayNoCommandPrintsUsageAndGuiFailsClearly() {
        assertThat(java.awt.GraphicsEnvironment.isHeadless()).isTrue();
        int[] code = new int[1];
        String[] r = run(code);
        assertThat(code[0]).as("issue 34, item 11: as gui does").isEqualTo(2);
        assertThat(r[0]).contains("Usage: kdtree").contains("gui").contains("stats");
        assertThat(r[1]).contains("no display");
        r = run(code, "gui");
        assertThat(code[0]).isEqualTo(2);
        assertThat(r[1]).contains("no display");
        assertThat(GuiCommand.opened()).isFalse();
    }
}
