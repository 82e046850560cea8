package org.kdtree.measure;

import java.util.Arrays;
import java.util.Comparator;
import java.util.function.Supplier;

/**
 * The one way this project times something: {@code warmups} untimed runs (the JVM compiles the
 * hot code during those), then {@code runs} timed ones, and the median, as docs/benchmark-spec.md
 * asks for builds and ray sets. Used by {@code stats}, {@code raycast}, the trade-off study and the
 * nearest-neighbour study.
 */
public final class Timing {
    private Timing() {
    }

    /**
     * The run of median time and what it returned.
     *
     * @param value   what the task returned in that run
     * @param seconds its wall time, at least a nanosecond (so that a rate is always finite)
     * @param <T>     the task's result
     */
    public record Timed<T>(T value, double seconds) {
        /** {@return the time in milliseconds} */
        public double millis() { return seconds * 1e3; }
    }

    /** Told before each run, e.g. to move a progress bar. */
    @FunctionalInterface
    public interface Progress {
        /**
         * Run {@code i} (0-based, warm-ups first) is about to start.
         *
         * @param i      the run's number
         * @param warmUp whether it is an untimed warm-up run
         */
        void before(int i, boolean warmUp);
    }

    /** Reports nothing. */
    public static final Progress QUIET = (i, warmUp) -> { };

    /**
     * Runs {@code task} {@code warmups + runs} times and returns the timed run of median time
     * (the upper median for an even count).
     *
     * @param warmups  untimed runs first, >= 0
     * @param runs     timed runs, >= 1
     * @param progress told before each run
     * @param task     the work to time
     * @param <T>      its result
     * @return the median run: its result and its time
     */
    public static <T> Timed<T> median(int warmups, int runs, Progress progress, Supplier<T> task) {
        if (warmups < 0 || runs < 1) throw new IllegalArgumentException("need warm-ups >= 0 and runs >= 1, got " + warmups + ", " + runs);
        @SuppressWarnings("unchecked")
        Timed<T>[] timed = new Timed[runs];
        for (int i = 0; i < warmups + runs; i++) {
            progress.before(i, i < warmups);
            long t0 = System.nanoTime();
            T value = task.get();
            long nanos = Math.max(1, System.nanoTime() - t0);
            if (i >= warmups) timed[i - warmups] = new Timed<>(value, nanos / 1e9);
        }
        Arrays.sort(timed, Comparator.comparingDouble(Timed::seconds));
        return timed[runs / 2];
    }

    /**
     * {@link #median(int, int, Progress, Supplier)} for work that returns nothing.
     *
     * @param warmups untimed runs first
     * @param runs    timed runs
     * @param task    the work to time
     * @return the median time in seconds
     */
    public static double medianSeconds(int warmups, int runs, Runnable task) {
        return median(warmups, runs, QUIET, () -> {
            task.run();
            return null;
        }).seconds();
    }
}
