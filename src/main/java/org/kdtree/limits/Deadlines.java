package org.kdtree.limits;

/**
 * How long a supervised build may take: one call of the builder's {@code terminate} or
 * {@code findPlane} (past it, the builder is hung in that method), and the whole build (past
 * it, while calls keep returning, the builder is slow). A builder's code is a student's, so
 * whoever runs it says how long to wait; each use has its defaults here, stated once
 * (docs/limits.md).
 *
 * @param callSeconds  the longest one call may take, in seconds ({@link Limits#CALL_DEADLINE})
 * @param buildSeconds the longest the whole build may take, in seconds ({@link Limits#BUILD_DEADLINE})
 */
public record Deadlines(double callSeconds, double buildSeconds) {
    /**
     * {@code grade} and the builder contract: the contract's scenes take the library's builders
     * well under a second, so 10 s for a call and 30 s for a build leave room for a slow machine
     * and still end a hung grading run in well under a minute and a half.
     */
    public static final Deadlines GRADE = new Deadlines(10, 30);

    /**
     * The workbench: its 2-D scenes take the library's builders milliseconds, and a user waits
     * for a window, not a report: 3 s for a call, 10 s for a build.
     */
    public static final Deadlines WORKBENCH = new Deadlines(3, 10);

    /**
     * {@code stats}, {@code raycast}, {@code render} and {@code tradeoff} with a plug-in builder:
     * a scene may hold millions of triangles, so a call may take a minute (a sort of every
     * primitive at the root) and a build ten.
     */
    public static final Deadlines COMMAND_LINE = new Deadlines(60, 600);

    /**
     * Deadlines within their limits.
     *
     * @param callSeconds  the longest one call may take, in seconds
     * @param buildSeconds the longest the whole build may take, in seconds
     * @throws IllegalArgumentException if either is outside its limit
     */
    public Deadlines {
        Limits.CALL_DEADLINE.check("call deadline", callSeconds);
        Limits.BUILD_DEADLINE.check("build deadline", buildSeconds);
    }

    /**
     * {@return these deadlines with either replaced} (null keeps this one's)
     *
     * @param call  the call deadline in seconds, or null
     * @param build the build deadline in seconds, or null
     */
    public Deadlines with(Double call, Double build) {
        return new Deadlines(call != null ? call : callSeconds, build != null ? build : buildSeconds);
    }
}
