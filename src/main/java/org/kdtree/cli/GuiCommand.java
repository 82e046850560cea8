package org.kdtree.cli;

import java.awt.GraphicsEnvironment;
import java.util.concurrent.Callable;
import org.kdtree.gui.Workbench;
import org.kdtree.spec.BuilderSpec;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;

/** {@code gui}: opens the Swing workbench (also what the jar does when given no command). */
@Command(name = "gui", mixinStandardHelpOptions = true,
        description = "Open the workbench: watch 2-D builds, step through a traversal, compare builders; "
                + "the builder options choose the builder and settings it starts with.")
final class GuiCommand implements Callable<Integer> {
    @Mixin
    BuilderOptions options = new BuilderOptions("sah");

    @Override public Integer call() {
        if (GraphicsEnvironment.isHeadless()) {
            System.err.println("error: no display available for the workbench (set DISPLAY, or use a command such as 'stats')");
            return 2;
        }
        BuilderSpec spec = options.spec();
        // an unknown builder, or a setting it does not take, is one line here, not in the window (bvh opens it too)
        spec.structureBuilder();
        Workbench.open(spec);
        opened = true;
        return 0;
    }

    private static volatile boolean opened;

    /** Whether a workbench window was opened by this JVM (then {@code main} must not exit). */
    static boolean opened() { return opened; }
}
