package org.kdtree.cli;

import java.io.PrintStream;
import java.util.Locale;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;

/**
 * How a long command says where it is, the one rule for every command ({@link #forCommand}):
 * on a terminal, a one-line bar on standard error redrawn in place every second (units done out
 * of a total, the step under way, the time so far), so that a long single step still shows
 * life; in a log (standard error not a terminal), no {@code \r} redraws but one plain line every
 * {@value #LOG_EVERY_SECONDS} seconds once the command has run that long, so short runs leave the
 * log clean; with {@code --quiet}, nothing. Safe to update from several threads.
 */
final class ProgressBar implements AutoCloseable {
    private static final int WIDTH = 30;
    /** In a log, the seconds between two progress lines, the first after as long. */
    static final int LOG_EVERY_SECONDS = 10;
    private final PrintStream out;
    private final boolean log;
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
        this(out, total, unit, false, 1000);
    }

    /**
     * @param log    plain lines for a log instead of a bar redrawn in place
     * @param everyMillis how often the bar is redrawn, or a log line written
     */
    ProgressBar(PrintStream out, int total, String unit, boolean log, long everyMillis) {
        this.out = out;
        this.log = log;
        this.total = Math.max(1, total);
        this.unit = unit;
        this.clock = out == null ? null : Executors.newSingleThreadScheduledExecutor(r -> {
            Thread t = new Thread(r, "progress");
            t.setDaemon(true);
            return t;
        });
        if (clock != null) clock.scheduleAtFixedRate(log ? this::logLine : this::redraw, everyMillis, everyMillis, TimeUnit.MILLISECONDS);
    }

    /** The progress a command shows (the rule above): a bar on a terminal, lines in a log, nothing when {@code quiet}. */
    static ProgressBar forCommand(boolean quiet, int total, String unit) {
        if (quiet) return new ProgressBar(null, total, unit);
        if (onTerminal()) return new ProgressBar(System.err, total, unit);
        return new ProgressBar(System.err, total, unit, true, LOG_EVERY_SECONDS * 1000L);
    }

    /**
     * Whether the command runs on a terminal. From JDK 22 on, {@code System.console()} is there in a
     * log too, and only its {@code isTerminal()} (absent from Java 17) tells.
     */
    static boolean onTerminal() {
        java.io.Console console = System.console();
        if (console == null) return false;
        try {
            return (Boolean) java.io.Console.class.getMethod("isTerminal").invoke(console);
        } catch (ReflectiveOperationException e) {
            return true;   // Java 17 to 21: a console is a terminal
        }
    }

    /** Whether this bar writes a log's plain lines (not a terminal, not quiet). */
    boolean writesLogLines() {
        return out != null && log;
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

    /** A log's line: where the command is, without redrawing. */
    private synchronized void logLine() {
        out.println(String.format(Locale.ROOT, "progress: %.0f s, %d of %d %s%s", (System.nanoTime() - start) / 1e9, done, total, unit,
                step.isEmpty() ? "" : ", " + step));
        out.flush();
    }

    private void draw() {
        if (out == null || log) return;
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
