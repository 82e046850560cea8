package org.kdtree.cli;

import org.kdtree.limits.Limits;
import picocli.CommandLine.Option;

/**
 * The {@code --runs} and {@code --warmup} options of the commands that time with
 * {@code measure.Timing} (a picocli mixin): each command gives its own defaults, the ranges and
 * the wording are the same everywhere.
 */
final class TimedRunsOptions {
    @Option(paramLabel = "N", names = "--runs", description = "Timed runs; the median is reported (default: ${DEFAULT-VALUE}).")
    int runs;

    @Option(paramLabel = "N", names = "--warmup", description = "Untimed runs first, to warm up the JVM (default: ${DEFAULT-VALUE}).")
    int warmup;

    TimedRunsOptions(int runs, int warmup) {
        this.runs = runs;
        this.warmup = warmup;
    }

    /** Refuses counts outside {@code Limits.RUNS} and {@code Limits.WARMUP}, naming the option. */
    void check() {
        Limits.RUNS.check("--runs", runs);
        Limits.WARMUP.check("--warmup", warmup);
    }
}
