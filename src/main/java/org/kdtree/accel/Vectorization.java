package org.kdtree.accel;

import java.lang.invoke.MethodHandles;
import java.lang.invoke.MethodType;

/**
 * Which kernels the traversals use (Apache Lucene's {@code VectorizationProvider} pattern): the
 * Java 17 kernels are everyone's; a structure swaps in its Vector API kernels, compiled separately
 * ({@code src/vector/java}, for JDK 21 with {@code jdk.incubator.vector}) and loaded reflectively,
 * only when this JVM is JDK 21 or later with the incubator module in its boot layer
 * ({@code --add-modules jdk.incubator.vector}, for instance in {@code JDK_JAVA_OPTIONS}) and the
 * system property {@code kdtree.vector} is not {@code false}. Both kinds of kernel give the same
 * hits, bit for bit. What is swapped is a small kernel, never a loop: each structure's loops are
 * written once and call whichever kernel {@link #kernel} chose at start-up.
 */
public final class Vectorization {
    /** The incubator module the vector path needs. */
    public static final String MODULE = "jdk.incubator.vector";
    /** The oldest JDK the vector kernels are compiled for and load on. */
    public static final int JDK = 21;
    private static volatile String reason = detect();

    private Vectorization() {
    }

    /** Why the JVM cannot use the vector path, or null if it can. */
    private static String detect() {
        if ("false".equals(System.getProperty("kdtree.vector"))) return "-Dkdtree.vector=false";
        int feature = Runtime.version().feature();
        if (feature < JDK) return "JDK " + feature + " (the vector path needs JDK " + JDK + " or newer)";
        if (ModuleLayer.boot().findModule(MODULE).isEmpty()) return "no --add-modules " + MODULE;
        return null;
    }

    /** {@return whether the traversals use their Vector API kernels in this JVM} */
    public static boolean enabled() {
        return reason == null;
    }

    /**
     * {@return the kernel a structure's loops call}: the Vector API class named {@code vectorClass}
     * (made with its public no-argument constructor) when {@link #enabled}, otherwise, or if it
     * does not load (a jar built without the vector classes), {@code scalar}, and the path turns
     * scalar for the whole JVM with the reason in {@link #describe}.
     *
     * @param <K>         the kernel's interface
     * @param kind        the kernel's interface
     * @param vectorClass the binary name of its Vector API implementation
     * @param scalar      its Java 17 implementation
     */
    public static <K> K kernel(Class<K> kind, String vectorClass, K scalar) {
        if (!enabled()) return scalar;
        try {
            Class<?> c = Class.forName(vectorClass, true, kind.getClassLoader());
            Object k = MethodHandles.publicLookup().findConstructor(c, MethodType.methodType(void.class)).invoke();
            return kind.cast(k);
        } catch (Throwable e) {
            reason = vectorClass.substring(vectorClass.lastIndexOf('.') + 1) + " did not load: " + e;
            return scalar;
        }
    }

    /** {@return which path the traversals take, and why}: "vector (...)" or "scalar (...)" */
    public static String describe() {
        String r = reason;
        return r == null ? "vector (" + MODULE + ", JDK " + Runtime.version().feature() + ")" : "scalar (Java 17 path: " + r + ")";
    }
}
