package org.kdtree.cli;

import picocli.CommandLine.Option;

/** The {@code --quiet} option of the commands that can run long (a picocli mixin). */
final class ProgressOption {
    @Option(names = {"-q", "--quiet"}, description = "No progress: no bar on a terminal, no progress lines in a log.")
    boolean quiet;

    /** Progress over {@code total} units, as {@link ProgressBar#forCommand} shows it. */
    ProgressBar bar(int total, String unit) {
        return ProgressBar.forCommand(quiet, total, unit);
    }
}
