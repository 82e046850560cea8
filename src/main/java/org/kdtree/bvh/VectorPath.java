package org.kdtree.bvh;

import java.lang.invoke.MethodHandle;
import java.lang.invoke.MethodHandles;
import java.lang.invoke.MethodType;
import org.kdtree.accel.PacketQuery;
import org.kdtree.accel.Vectorization;
import org.kdtree.accel.RayQuery;

/**
 * The BVH's vector traversals, found at run time: {@code VectorTraversal} (single rays) and
 * {@code VectorPacketTraversal} (packets, rays in the lanes) live in their own source folder
 * ({@code src/vector/java}), compiled for JDK 21 with {@code jdk.incubator.vector}, and are
 * loaded reflectively only when {@link Vectorization#enabled}, so that this package's code stays
 * Java 17 bytecode and runs without it.
 */
final class VectorPath {
    /** {@code VectorTraversal(Bvh)}, or null on the Java 17 path. */
    private static final MethodHandle MAKE = find("org.kdtree.bvh.VectorTraversal", MethodType.methodType(void.class, Bvh.class));
    /** {@code VectorPacketTraversal(Bvh, RayQuery)}, or null on the Java 17 path. */
    private static final MethodHandle PACKETS = find("org.kdtree.bvh.VectorPacketTraversal",
            MethodType.methodType(void.class, Bvh.class, RayQuery.class));
    /** How many children the vector traversal tests at once (its lanes), or 0. */
    static final int LANES = lanes();

    private VectorPath() {
    }

    private static MethodHandle find(String name, MethodType constructor) {
        if (!Vectorization.enabled()) return null;
        try {
            return MethodHandles.lookup().findConstructor(Class.forName(name), constructor);
        } catch (ReflectiveOperationException | LinkageError e) {
            Vectorization.unavailable("the vector traversal did not load: " + e);
            return null;
        }
    }

    private static int lanes() {
        if (MAKE == null || PACKETS == null) return 0;
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

    /**
     * {@return the vector packet traversal of {@code bvh} (rays in the lanes), tracing single rays with {@code single}};
     * only when {@link #enabled}
     * @param bvh    a hierarchy over a triangle mesh
     * @param single its single-ray query
     */
    static PacketQuery packets(Bvh bvh, RayQuery single) {
        try {
            return (PacketQuery) PACKETS.invoke(bvh, single);
        } catch (RuntimeException | Error e) {
            throw e;
        } catch (Throwable e) {
            throw new IllegalStateException(e);
        }
    }
}
