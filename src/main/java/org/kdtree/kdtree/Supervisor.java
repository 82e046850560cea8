package org.kdtree.kdtree;

import java.util.Locale;
import java.util.concurrent.CancellationException;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.FutureTask;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import org.kdtree.limits.Deadlines;
import org.kdtree.limits.Limit;
import org.kdtree.shape.Primitives;

/**
 * Builds a tree with an untrusted builder (a student's, a plug-in's) without trusting it to
 * return: the build runs on a daemon thread of its own, named after the builder, and the calling
 * thread watches it. A call of {@code terminate} or {@code findPlane} still under way after the
 * call deadline is a builder {@link BuilderFault.Kind#HUNG hung} in that method; a build still
 * running after the build deadline while its calls keep returning is {@link BuilderFault.Kind#SLOW
 * slow}, reported with its time per node against the library's median plane on the same scene.
 * Either way the build is stopped: cancelled at its next node, its thread interrupted and, if it
 * spins on regardless, stopped ({@link Thread#stop}, which Java 17 still has), so that no thread
 * stays spinning. What the builder throws or answers wrongly comes back as the recursion's
 * {@link BuilderFault}; the calling thread being interrupted cancels the build.
 *
 * <pre>{@code
 * KdTree tree = Supervisor.of(Deadlines.COMMAND_LINE).trustingTheLibrary().build(builder, mesh);
 * }</pre>
 */
public final class Supervisor {
    /** How often the watcher reads the build's progress. */
    private static final long POLL_MILLIS = 50;
    /** How long a stopped build's thread is given to end: at its next node, or at its next look at its interrupt. */
    private static final long GRACE_MILLIS = 300;

    private final Deadlines deadlines;
    private final boolean trustLibrary;

    private Supervisor(Deadlines deadlines, boolean trustLibrary) {
        this.deadlines = deadlines;
        this.trustLibrary = trustLibrary;
    }

    /**
     * A supervisor of every builder.
     *
     * @param deadlines how long a call and a build may take
     * @return the supervisor
     */
    public static Supervisor of(Deadlines deadlines) {
        return new Supervisor(deadlines, false);
    }

    /**
     * {@return a supervisor that builds with the library's own builders directly, on the calling
     * thread, so that their timings stay what they are, and supervises every other}
     * ({@link #isLibrarys})
     */
    public Supervisor trustingTheLibrary() {
        return new Supervisor(deadlines, true);
    }

    /** {@return the deadlines of a call and of a build} */
    public Deadlines deadlines() { return deadlines; }

    /**
     * Builds the tree of {@code primitives} with {@code builder}, within the deadlines.
     *
     * @param builder the builder
     * @param primitives the scene
     * @return the tree
     * @throws BuilderFault if the builder threw, gave an answer the recursion cannot use, hung in a
     *         call, or was too slow; its message is one line naming the builder, the method and the node
     * @throws CancellationException if the calling thread was interrupted (the build is stopped)
     */
    public KdTree build(KdTreeBuilder builder, Primitives primitives) {
        if (trustLibrary && isLibrarys(builder)) return builder.build(primitives);
        BuildWatch watch = BuildWatch.watched();
        FutureTask<KdTree> task = new FutureTask<>(() -> builder.build(primitives, watch));
        Thread worker = new Thread(task, "build by " + builder.name());
        worker.setDaemon(true);
        worker.start();
        try {
            return watch(builder, primitives, task, worker, watch);
        } catch (ExecutionException e) {
            throw rethrown(e.getCause());
        } catch (InterruptedException e) {
            stop(worker, watch);
            Thread.currentThread().interrupt();
            throw new CancellationException("build by " + builder.name() + " cancelled");
        }
    }

    /** Waits for the build, reading its watch every {@link #POLL_MILLIS}, until it ends or misses a deadline. */
    private KdTree watch(KdTreeBuilder builder, Primitives primitives, FutureTask<KdTree> task, Thread worker, BuildWatch watch)
            throws ExecutionException, InterruptedException {
        long start = System.nanoTime(), callSince = start, lastCalls = 0;
        long callNanos = nanos(deadlines.callSeconds()), buildNanos = nanos(deadlines.buildSeconds());
        while (true) {
            try {
                return task.get(POLL_MILLIS, TimeUnit.MILLISECONDS);
            } catch (TimeoutException stillRunning) {
                long now = System.nanoTime(), calls = watch.calls();
                if (calls != lastCalls) {
                    lastCalls = calls;
                    callSince = now;
                }
                if (watch.inCall() && now - callSince > callNanos) {
                    String method = watch.method();
                    int depth = watch.depth(), size = watch.size();
                    boolean stopped = stop(worker, watch);
                    throw hung(builder, method, depth, size, stopped);
                }
                if (now - start > buildNanos) {
                    long nodes = watch.nodes();
                    boolean stopped = stop(worker, watch);
                    throw slow(builder, primitives, nodes, now - start, stopped);
                }
            }
        }
    }

    /**
     * Stops the build: cancels it at its next node, interrupts its thread, and if the thread
     * still runs after a grace period (a loop that never reaches a node nor looks at its
     * interrupt), stops it; where the JVM cannot (Java 20 and later), leaves it at the lowest
     * priority.
     *
     * @return whether the thread has ended
     */
    @SuppressWarnings({"deprecation", "removal"})
    private static boolean stop(Thread worker, BuildWatch watch) {
        watch.cancel(null);
        worker.interrupt();
        if (ended(worker)) return true;
        try {
            worker.stop(); // ThreadDeath unwinds the builder's code; the build's task swallows it and the thread ends
        } catch (UnsupportedOperationException noStopOnThisJava) {
            worker.setPriority(Thread.MIN_PRIORITY);
            return false;
        }
        return ended(worker);
    }

    private static boolean ended(Thread worker) {
        try {
            worker.join(GRACE_MILLIS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        return !worker.isAlive();
    }

    private BuilderFault hung(KdTreeBuilder builder, String method, int depth, int size, boolean stopped) {
        return new BuilderFault(builder.name(), BuilderFault.Kind.HUNG, method, depth, size,
                "did not return within " + seconds(deadlines.callSeconds()),
                stoppedOrNot(stopped) + ": look for a loop that never ends in " + method, null);
    }

    /**
     * A slow build, measured against the library's median plane on the same scene (built after
     * the slow build was stopped, so that the two do not share the processor).
     */
    private BuilderFault slow(KdTreeBuilder builder, Primitives primitives, long nodes, long nanos, boolean stopped) {
        long t0 = System.nanoTime();
        KdTree median = new MedianPlaneBuilder().build(primitives);
        double medianPerNode = (System.nanoTime() - t0) / 1e6 / median.nodeCount();
        String took = "stopped after " + seconds(nanos / 1e9) + " at " + nodes + (nodes == 1 ? " node" : " nodes");
        String problem = nodes == 0
                ? "slow: not one node done, against " + millis(medianPerNode) + " per node for the library's median plane on this scene; " + took
                : "slow: " + millis(nanos / 1e6 / nodes) + " per node against " + millis(medianPerNode)
                        + " per node for the library's median plane on this scene; " + took;
        return new BuilderFault(builder.name(), BuilderFault.Kind.SLOW, null, -1, -1, problem,
                (stopped ? "" : "its thread could not be stopped; ") + "look for work repeated on every call (sorting every primitive, sleeping)",
                null);
    }

    private static String stoppedOrNot(boolean stopped) {
        return stopped ? "it was stopped"
                : "its thread could not be stopped (this Java has no Thread.stop) and runs on at the lowest priority";
    }

    private static RuntimeException rethrown(Throwable cause) {
        if (cause instanceof RuntimeException r) return r;
        if (cause instanceof Error e) throw e;
        return new IllegalStateException(cause);
    }

    private static long nanos(double seconds) {
        return (long) (seconds * 1e9);
    }

    /** "10 s", "0.5 s", "31 s": seconds as people read them. */
    private static String seconds(double s) {
        return Limit.format(s >= 10 ? Math.rint(s) : Math.rint(s * 10) / 10) + " s";
    }

    /** "201 ms", "1.4 ms", "0.002 ms": one or two significant digits below 10 ms, whole ones above. */
    private static String millis(double ms) {
        if (ms >= 10) return String.format(Locale.ROOT, "%.0f ms", ms);
        if (ms >= 1) return String.format(Locale.ROOT, "%.1f ms", ms);
        return String.format(Locale.ROOT, "%.1g ms", ms).replaceFirst("e-0?(\\d+)", "e-$1");
    }

    /**
     * Whether {@code builder} is one of the library's own (its builders and the course's worked
     * example), whose code is trusted to return and is timed as it is; any other (a student's,
     * a plug-in's) runs under a {@link Supervisor} on the command line.
     *
     * @param builder a builder
     * @return true if its class is the library's, loaded with the library
     */
    public static boolean isLibrarys(KdTreeBuilder builder) {
        Class<?> c = builder.getClass();
        String own = Supervisor.class.getPackageName(), pkg = c.getPackageName();
        String examples = own.substring(0, own.lastIndexOf('.')) + ".examples"; // the course's example, no package named here
        return c.getClassLoader() == Supervisor.class.getClassLoader() && (pkg.equals(own) || pkg.equals(examples));
    }
}
