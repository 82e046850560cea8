package org.kdtree.bvh;

/**
 * Whether the traversals may use the Vector API (Apache Lucene's {@code VectorizationProvider}
 * pattern): the Java 17 path is everyone's, and a structure switches to its vector code, compiled
 * separately for JDK 25 and loaded reflectively, only when this JVM is JDK 25 or later with the
 * incubator module {@code jdk.incubator.vector} in its boot layer
 * ({@code --add-modules jdk.incubator.vector}, for instance in {@code JDK_JAVA_OPTIONS}) and the
 * system property {@code kdtree.vector} is not {@code false}. Both paths give the same hits, bit
 * for bit. A structure whose vector code fails to load reports it here ({@link #unavailable}),
 * and traces on the Java 17 path.
 */
final class Vectorization {
    /** The incubator module the vector path needs. */
    public static final String MODULE = "jdk.incubator.vector";
    /** The JDK the vector code is compiled for, and the oldest that loads it. */
    public static final int JDK = 25;
    private static volatile String reason = detect();

    private Vectorization() {
    }

    /** Why the JVM cannot use the vector path, or null if it can. */
    private static String detect() {
        if ("false".equals(System.getProperty("kdtree.vector"))) return "-Dkdtree.vector=false";
        int feature = Runtime.version().feature();
        if (feature < JDK) return "JDK " + feature + " (the vector path needs JDK " + JDK + ")";
        if (ModuleLayer.boot().findModule(MODULE).isEmpty()) return "no --add-modules " + MODULE;
        return null;
    }

    /** {@return whether structures trace with the Vector API in this JVM} */
    public static boolean enabled() {
        return reason == null;
    }

    /**
     * Turns the vector path off for this JVM: a structure's vector code did not load.
     *
     * @param why what failed, for {@link #describe}
     */
    public static void unavailable(String why) {
        reason = why;
    }

    /** {@return which path the traversals take, and why}: "vector (...)" or "scalar (...)" */
    public static String describe() {
        String r = reason;
        return r == null ? "vector (" + MODULE + ", JDK " + Runtime.version().feature() + ")" : "scalar (Java 17 path: " + r + ")";
    }
}
