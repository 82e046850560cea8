package org.kdtree.kdtree;

/**
 * A builder's own fault, found while the recursion ran it: its {@code terminate} or
 * {@code findPlane} threw, gave an answer the recursion cannot use (no plane, a plane on an axis
 * the scene does not have, outside the node's voxel, at no finite position), did not return
 * within its deadline, or was too slow to finish. The message is one line that names the
 * builder, the method, the node (its depth and size), what was wrong, and a hint, so that a
 * student reads what to fix and nobody blames the library.
 */
public final class BuilderFault extends RuntimeException {
    private static final long serialVersionUID = 1L;

    /** What went wrong. */
    public enum Kind {
        /** The method threw. */
        THREW,
        /** The method returned something the recursion cannot use. */
        BAD_ANSWER,
        /** The method did not return within its deadline. */
        HUNG,
        /** Every call returned, but the whole build did not finish within its deadline. */
        SLOW
    }

    /** {@code terminate}, {@code findPlane}: the methods a builder implements, as the talk names them. */
    public static final String TERMINATE = "terminate", FIND_PLANE = "findPlane";

    /** The builder's name. */
    private final String builder;
    /** What went wrong. */
    private final Kind kind;
    /** The method to blame, or null. */
    private final String method;
    /** The node's depth, or -1. */
    private final int depth;
    /** The node's number of primitives, or -1. */
    private final int size;
    /** What was wrong, as a clause. */
    private final String problem;
    /** What to do about it. */
    private final String hint;

    /**
     * @param builder the builder's name
     * @param kind what went wrong
     * @param method {@link #TERMINATE} or {@link #FIND_PLANE}; null when no one call is to blame (a slow build)
     * @param depth the node's depth, or -1 if unknown
     * @param size the node's number of primitives, or -1 if unknown
     * @param problem what was wrong, as a clause ("threw ArithmeticException: / by zero")
     * @param hint what to do about it, as a sentence
     * @param cause what the builder threw, or null
     */
    public BuilderFault(String builder, Kind kind, String method, int depth, int size, String problem, String hint,
                        Throwable cause) {
        super(cause);
        this.builder = builder;
        this.kind = kind;
        this.method = method;
        this.depth = depth;
        this.size = size;
        this.problem = problem;
        this.hint = hint;
    }

    /** {@return the builder's name} */
    public String builder() { return builder; }

    /** {@return what went wrong} */
    public Kind kind() { return kind; }

    /** {@return {@link #TERMINATE} or {@link #FIND_PLANE}, or null when no one call is to blame} */
    public String method() { return method; }

    /** {@return the depth of the node it failed on, or -1} */
    public int depth() { return depth; }

    /** {@return the number of primitives of the node it failed on, or -1} */
    public int size() { return size; }

    /** {@return what was wrong, as a clause} */
    public String problem() { return problem; }

    /** {@return what to do about it} */
    public String hint() { return hint; }

    /** One line: "builder NAME: METHOD PROBLEM, at depth D on a node of N primitives; HINT". */
    @Override public String getMessage() {
        StringBuilder s = new StringBuilder("builder ").append(builder).append(": ");
        if (method != null) s.append(method).append(' ');
        s.append(problem);
        if (depth >= 0) s.append(", at depth ").append(depth).append(" on a node of ").append(size)
                .append(size == 1 ? " primitive" : " primitives");
        if (hint != null && !hint.isEmpty()) s.append("; ").append(hint);
        return s.toString();
    }
}
