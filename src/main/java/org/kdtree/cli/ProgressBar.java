package org.kdtree.cli;

import java.io.PrintStream;
import java.util.Locale;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;

/**
 * A one-line progress bar on a terminal, redrawn in place: units done out of a total, the step
 * under way, and the time it has taken so far, redrawn every second so that a long single step
 * (one build of a large scene) still shows life. Safe to update from several threads.
 *
 * <p>Commands make one with {@link #onTerminal}: when the output is a log, not a terminal,
 * there is no bar at all, since {@code \r} redraws would fill the log.
 */
final class ProgressBar implements AutoCloseable {
    private static final int WIDTH = 30;
    private final PrintStream out;
    private int total;
    private final String unit;
    private final long start = System.nanoTime();
    private final ScheduledExecutorService clock;
    private int done;
    private String step = "";
    private int shownPercent = -1;
    private boolean drawn;

    /**
     * @param out   where to draw (stderr, so stdout stays clean for the results); null for no bar
     * @param total units of work in all
     * @param unit  what a unit is, plural ("tiles", "steps")
     */
    ProgressBar(PrintStream out, int total, String unit) {
        this.out = out;
        this.total = Math.max(1, total);
        this.unit = unit;
        this.clock = out == null ? null : Executors.newSingleThreadScheduledExecutor(r -> {
            Thread t = new Thread(r, "progress");
            t.setDaemon(true);
            return t;
        });
        if (clock != null) clock.scheduleAtFixedRate(this::redraw, 1, 1, TimeUnit.SECONDS);
    }

    /** A bar on standard error if it is a terminal and {@code quiet} is off; otherwise none. */
    static ProgressBar onTerminal(boolean quiet, int total, String unit) {
        return new ProgressBar(!quiet && System.console() != null ? System.err : null, total, unit);
    }

    /** Reports that {@code doneNow} units are finished (threads may report out of order: it never moves backwards). */
    synchronized void update(int doneNow) {
        if (doneNow <= done) return;
        done = doneNow;
        int percent = (int) (100L * done / total);
        if (percent > shownPercent) draw();
    }

    /** Reports progress where the total is known only by the worker (the renderer's tile count). */
    synchronized void update(int doneNow, int totalNow) {
        total = Math.max(1, totalNow);
        update(doneNow);
    }

    /** Starts a named step (for example "build 2 of 5"), counting the steps before it as done. */
    synchronized void step(int index, String name) {
        step = name;
        done = Math.max(done, index);
        draw();
    }

    /** Writes {@code line} to {@code stream} above the bar, which is then drawn again. */
    synchronized void print(PrintStream stream, String line) {
        clear();
        stream.println(line);
        stream.flush();
        if (drawn) draw();
    }

    /** Ends the bar's line (stops the clock); the terminal is left clean for what follows. */
    @Override public synchronized void close() {
        if (clock != null) clock.shutdownNow();
        clear();
        drawn = false;
    }

    private synchronized void redraw() {
        if (drawn) draw();
    }

    private void draw() {
        if (out == null) return;
        int percent = (int) (100L * done / total);
        shownPercent = percent;
        int filled = WIDTH * done / total;
        out.print(String.format(Locale.ROOT, "\r[%s%s] %3d%% (%d/%d %s) %s %.0f s\033[K", "#".repeat(filled),
                "-".repeat(WIDTH - filled), percent, done, total, unit, step, (System.nanoTime() - start) / 1e9));
        out.flush();
        drawn = true;
    }

    private void clear() {
        if (out == null || !drawn) return;
        out.print("\r\033[K");
        out.flush();
    }
}
