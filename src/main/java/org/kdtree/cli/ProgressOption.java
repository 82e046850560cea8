package org.kdtree.cli;

import picocli.CommandLine.Option;

/** The {@code --quiet} option of the commands that can run long (a picocli mixin). */
final class ProgressOption {
    @Option(names = {"-q", "--quiet"}, description = "No progress bar (there is none either when the output is not a terminal).")
    boolean quiet;

    /** A bar on the terminal for {@code total} units, or a silent one. */
    ProgressBar bar(int total, String unit) {
        return ProgressBar.onTerminal(quiet, total, unit);
    }
}
