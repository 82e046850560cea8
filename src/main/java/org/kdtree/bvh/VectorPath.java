package org.kdtree.bvh;

import java.lang.invoke.MethodHandle;
import java.lang.invoke.MethodHandles;
import java.lang.invoke.MethodType;
import org.kdtree.accel.RayQuery;

/**
 * The BVH's vector traversal, found at run time: {@code VectorTraversal} lives in its own source
 * folder ({@code src/vector/java}), compiled for JDK 25 with {@code jdk.incubator.vector}, and is
 * loaded reflectively only when {@link Vectorization#enabled}, so that this package's code stays
 * Java 17 bytecode and runs without it.
 */
final class VectorPath {
    /** {@code VectorTraversal(Bvh)}, or null on the Java 17 path. */
    private static final MethodHandle MAKE = find();
    /** How many children the vector traversal tests at once (its lanes), or 0. */
    static final int LANES = lanes();

    private VectorPath() {
    }

    private static MethodHandle find() {
        if (!Vectorization.enabled()) return null;
        try {
            Class<?> c = Class.forName("org.kdtree.bvh.VectorTraversal");
            return MethodHandles.lookup().findConstructor(c, MethodType.methodType(void.class, Bvh.class));
        } catch (ReflectiveOperationException | LinkageError e) {
            Vectorization.unavailable("the vector traversal did not load: " + e);
            return null;
        }
    }

    private static int lanes() {
        if (MAKE == null) return 0;
        try {
            return (int) MethodHandles.lookup().findStatic(MAKE.type().returnType(), "lanes", MethodType.methodType(int.class)).invoke();
        } catch (Throwable e) {
            Vectorization.unavailable("the vector traversal did not load: " + e);
            return 0;
        }
    }

    /** {@return whether this JVM traces with the vector traversal} */
    static boolean enabled() {
        return LANES > 0;
    }

    /** {@return the vector traversal of {@code bvh} over its triangles}; only when {@link #enabled}. */
    static RayQuery query(Bvh bvh) {
        try {
            return (RayQuery) MAKE.invoke(bvh);
        } catch (RuntimeException | Error e) {
            throw e;
        } catch (Throwable e) {
            throw new IllegalStateException(e);
        }
    }
}
