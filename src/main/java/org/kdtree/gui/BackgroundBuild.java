package org.kdtree.gui;

import java.util.concurrent.CancellationException;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.function.Consumer;
import javax.swing.SwingUtilities;
import org.kdtree.kdtree.BuilderFault;
import org.kdtree.kdtree.Supervisor;
import org.kdtree.limits.Deadlines;
import org.kdtree.shape.Primitives;
import org.kdtree.spec.BuilderSpec;

/**
 * The workbench's builds, off the event thread: one at a time on a thread of their own, a
 * plug-in's under a {@link Supervisor} with the workbench's {@link Deadlines} (the library's own
 * builders, the bounding volume hierarchy's too, are trusted to return, and obey interruption).
 * A new build cancels the one under way; only the newest build's outcome is delivered, once, on
 * the event thread.
 */
final class BackgroundBuild {
    /** A build's end: its kd-tree or hierarchy, or its builder's fault; and how long it took. */
    record Outcome(Built built, BuilderFault fault, double millis) {
    }

    private final Supervisor supervisor = Supervisor.of(Deadlines.WORKBENCH).trustingTheLibrary();
    private final ExecutorService thread;
    private Future<Outcome> pending;
    private int started, delivered;

    /** @param name the build thread's name */
    BackgroundBuild(String name) {
        thread = Executors.newSingleThreadExecutor(r -> {
            Thread t = new Thread(r, name);
            t.setDaemon(true);
            return t;
        });
    }

    /**
     * How long the event thread waits for a build of a small scene by a plug-in's builder: a
     * hung one holds the window for no longer than this.
     */
    static final long PLUGIN_WAIT_MILLIS = 250;

    /**
     * How long the event thread waits for a build of a small scene by one of the library's
     * builders, which return in milliseconds (a busy machine's worst case: a cold JIT, a shared
     * processor): long enough that its tree appears within the event that changed the scene.
     */
    static final long LIBRARY_WAIT_MILLIS = 2_000;

    /**
     * Starts building {@code primitives} as {@code spec} says, a kd-tree or a hierarchy,
     * cancelling the build under way; for a {@code small} scene, waits for it on the calling
     * (event) thread, up to {@link #LIBRARY_WAIT_MILLIS} for the library's builders and
     * {@link #PLUGIN_WAIT_MILLIS} for any other.
     *
     * @return true if it ended within the wait and {@code done} has had its outcome; false if it
     *         still runs, and {@code done} will have it later, on the event thread
     * @throws IllegalArgumentException if {@code spec} names no builder or gives a setting it does not take
     */
    boolean start(BuilderSpec spec, Primitives primitives, boolean small, Consumer<Outcome> done) {
        boolean librarys = spec.librarys();
        long waitMillis = !small ? 0 : librarys ? LIBRARY_WAIT_MILLIS : PLUGIN_WAIT_MILLIS;
        int mine = next();
        if (pending != null) pending.cancel(true);
        Future<Outcome> job = thread.submit(() -> {
            Outcome o = build(spec, primitives);
            if (o != null) SwingUtilities.invokeLater(() -> deliver(mine, o, done));
            return o;
        });
        pending = job;
        if (waitMillis <= 0) return false;
        try {
            Outcome o = job.get(waitMillis, TimeUnit.MILLISECONDS);
            if (o != null) deliver(mine, o, done);
            return true;
        } catch (TimeoutException stillRunning) {
            return false;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return false;
        } catch (ExecutionException e) { // not the builder's fault: ours, as a build on this thread would have thrown it
            if (e.getCause() instanceof RuntimeException r) throw r;
            throw new IllegalStateException(e.getCause());
        }
    }

    /**
     * Builds on the build thread, a kd-tree builder under the supervisor (its faults are the
     * outcome), a hierarchy directly (the library's: trusted, it stops when interrupted); null if
     * cancelled (a newer build replaced it).
     */
    private Outcome build(BuilderSpec spec, Primitives primitives) {
        long t0 = System.nanoTime();
        try {
            return new Outcome(Built.of(spec.build(primitives, supervisor), spec), null, (System.nanoTime() - t0) / 1e6);
        } catch (BuilderFault f) {
            return new Outcome(null, f, (System.nanoTime() - t0) / 1e6);
        } catch (CancellationException replaced) {
            return null;
        }
    }

    private synchronized int next() {
        return ++started;
    }

    /**
     * Hands build {@code mine}'s outcome to {@code done}, once, unless a newer build was started.
     * The check and the hand-over hold one lock, as {@link #next} does: the waiting thread and the
     * event thread may both try (a caller off the event thread, as in tests), only one of them may
     * find it undelivered, and an outcome in hand cannot be shown after a newer build's.
     */
    private synchronized void deliver(int mine, Outcome o, Consumer<Outcome> done) {
        if (mine != started || mine == delivered) return;
        delivered = mine;
        done.accept(o);
    }
}
