package org.kdtree.bvh;

import java.lang.invoke.MethodHandle;
import java.lang.invoke.MethodHandles;
import java.lang.invoke.MethodType;
import org.kdtree.accel.PacketQuery;
import org.kdtree.accel.Vectorization;
import org.kdtree.accel.RayQuery;

/**
 * The BVH's vector packet traversal, found at run time: {@code VectorPacketTraversal} (packets, rays in the lanes) lives in its own source folder
 * ({@code src/vector/java}), compiled for JDK 21 with {@code jdk.incubator.vector}, and are
 * loaded reflectively only when {@link Vectorization#enabled}, so that this package's code stays
 * Java 17 bytecode and runs without it.
 */
final class VectorPath {
    /** {@code VectorPacketTraversal(Bvh, RayQuery)}, or null on the Java 17 path. */
    private static final MethodHandle PACKETS = find("org.kdtree.bvh.VectorPacketTraversal",
            MethodType.methodType(void.class, Bvh.class, RayQuery.class));
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

    /** {@return whether this JVM traces with the vector traversal} */
    static boolean enabled() {
        return PACKETS != null;
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
