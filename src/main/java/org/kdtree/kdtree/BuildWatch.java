package org.kdtree.kdtree;

import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.util.concurrent.CancellationException;

/**
 * What the recursion tells whoever watches a build, and how it is told to stop. The recursion
 * reports every node ({@link #node}) and every call into the builder ({@link #enter},
 * {@link #leave}); at every node it stops when the build is cancelled or its thread interrupted.
 * A watcher on another thread (a supervisor) reads {@link #calls()}, {@link #nodes()} and where
 * the last call went, to tell a hung call from a slow build.
 *
 * <p>Cheap enough for every build: an unwatched build only checks the cancel flag and its
 * thread's interrupt; a watched one adds a few plain stores and one release store per call.
 */
final class BuildWatch {
    /** The methods of the builder that the recursion calls. */
    static final int TERMINATE = 1, FIND_PLANE = 2;

    /**
     * How often (in nodes, a power of two) the recursion looks at its thread's interrupt flag: a
     * volatile read at every node cost the exact bunny build 6 %; every 64th node is still
     * well under a millisecond.
     */
    private static final int INTERRUPT_EVERY = 64;

    private static final VarHandle CALLS, OPEN, CANCELLED;

    static {
        try {
            CALLS = MethodHandles.lookup().findVarHandle(BuildWatch.class, "calls", long.class);
            OPEN = MethodHandles.lookup().findVarHandle(BuildWatch.class, "open", int.class);
            CANCELLED = MethodHandles.lookup().findVarHandle(BuildWatch.class, "cancelled", boolean.class);
        } catch (ReflectiveOperationException e) {
            throw new ExceptionInInitializerError(e);
        }
    }

    private final boolean watched;
    /** Set once by {@link #cancel}; read at every node without a fence (opaque), so it costs next to nothing. */
    @SuppressWarnings("unused") private boolean cancelled;
    private volatile RuntimeException stopWith;
    /** Incremented on entering and on leaving a call: it stands still while a call hangs or nothing is called. */
    @SuppressWarnings("unused") private long calls;
    /** The calls under way: 0 or 1 in a one-thread build. */
    @SuppressWarnings("unused") private int open;
    /** Whether several threads report to this watch (a parallel build): then the counts are updated atomically. */
    private boolean shared;
    private final java.util.concurrent.atomic.LongAdder nodes = new java.util.concurrent.atomic.LongAdder();
    private int method, depth, size;

    private BuildWatch(boolean watched) {
        this.watched = watched;
    }

    /** {@return a watch that nobody reads: it only stops the build when cancelled or interrupted} */
    static BuildWatch unwatched() {
        return new BuildWatch(false);
    }

    /** {@return a watch that a supervisor reads} */
    static BuildWatch watched() {
        return new BuildWatch(true);
    }

    /**
     * At every node: counts it, and stops the build if it was cancelled, or (every
     * {@link #INTERRUPT_EVERY}th node of the thread's {@code tick}) if its thread was interrupted.
     */
    void node(int tick) {
        if ((boolean) CANCELLED.getOpaque(this)) throw stopped();
        if ((tick & (INTERRUPT_EVERY - 1)) == 0 && Thread.currentThread().isInterrupted()) {
            cancel(null); // and so every thread of the build stops
            throw new CancellationException("build cancelled");
        }
        if (watched) nodes.increment();
    }

    /** Before the build starts: whether its nodes are built by several threads. */
    void threads(int n) {
        shared = n > 1;
    }

    /** Before the recursion calls the builder's {@code method} on a node. */
    void enter(int which, int nodeDepth, int nodeSize) {
        if (!watched) return;
        method = which;
        depth = nodeDepth;
        size = nodeSize;
        count(1);
    }

    /** After the call returned or threw. */
    void leave() {
        if (!watched) return;
        count(-1);
    }

    /** One more entry or exit; plain release stores on one thread, atomic updates on several. */
    private void count(int openDelta) {
        if (shared) {
            OPEN.getAndAdd(this, openDelta);
            CALLS.getAndAdd(this, 1L);
        } else {
            OPEN.setRelease(this, (int) OPEN.getOpaque(this) + openDelta);
            CALLS.setRelease(this, (long) CALLS.getOpaque(this) + 1);
        }
    }

    /**
     * Stops the build at its next node: it ends with {@code reason} (a {@link BuilderFault}
     * found by the watcher), or with a {@link CancellationException} if null. The first reason given stays.
     */
    void cancel(RuntimeException reason) {
        if (cancelled()) return;
        stopWith = reason;
        CANCELLED.setVolatile(this, true);
    }

    /** {@return whether the build was told to stop} */
    boolean cancelled() { return (boolean) CANCELLED.getVolatile(this); }

    private RuntimeException stopped() {
        RuntimeException reason = stopWith;
        return reason != null ? reason : new CancellationException("build cancelled");
    }

    /** {@return the count of entries into and exits from the builder's methods} */
    long calls() { return (long) CALLS.getAcquire(this); }

    /** {@return whether a call into the builder is under way} */
    boolean inCall() { return (int) OPEN.getAcquire(this) > 0; }

    /** {@return the nodes visited so far, by every thread of the build} */
    long nodes() { return nodes.sum(); }

    /** {@return {@link BuilderFault#TERMINATE} or {@link BuilderFault#FIND_PLANE}: the method of the last call} */
    String method() { return method == FIND_PLANE ? BuilderFault.FIND_PLANE : BuilderFault.TERMINATE; }

    /** {@return the depth of the node of the last call} */
    int depth() { return depth; }

    /** {@return the size of the node of the last call} */
    int size() { return size; }
}
