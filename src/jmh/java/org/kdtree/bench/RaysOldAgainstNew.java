package org.kdtree.bench;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.lang.reflect.Method;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Locale;
import java.util.function.Supplier;

/**
 * Traces one ray set with two versions of the library (or two variants of one) in one JVM, in
 * turn, as {@link OldAgainstNew} builds: each jar in a class loader of its own, traces
 * alternating and the order swapping every round, thread CPU time measured, one thread.
 *
 * <pre>
 * java [-Dgrid=4] -cp target/benchmarks.jar org.kdtree.bench.RaysOldAgainstNew OLD.jar NEW.jar MESH.obj RUNS P|R OLD_BUILDER NEW_BUILDER
 * </pre>
 * With {@code -Dgrid=N} both trace the mesh repeated in an N x N grid ({@code raycast --grid N}).
 * A BUILDER is {@code sah} (the exact kd-tree), {@code bvh} or {@code bvh:W} (the BVH traced
 * {@code W} wide). Prints each side's median and quartile in Mrays/s, the checksums, and new/old
 * (above 1: the new traces faster).
 */
public final class RaysOldAgainstNew {
    private RaysOldAgainstNew() {
    }

    public static void main(String[] args) throws Exception {
        if (args.length < 7) {
            System.err.println("usage: RaysOldAgainstNew OLD.jar NEW.jar MESH.obj RUNS P|R OLD_BUILDER NEW_BUILDER");
            System.exit(2);
        }
        int runs = Integer.parseInt(args[3]);
        Object[] batch = new Object[2], sets = new Object[2];
        Method[] trace = new Method[2];
        for (int i = 0; i < 2; i++) {
            ClassLoader cl = new URLClassLoader(new URL[] {Path.of(args[i]).toUri().toURL()}, ClassLoader.getPlatformClassLoader());
            Object mesh = cl.loadClass("org.kdtree.io.PrimitivesReader").getMethod("read", Path.class).invoke(null, Path.of(args[2]));
            Class<?> meshClass = cl.loadClass("org.kdtree.shape.TriangleMesh");
            int grid = Integer.getInteger("grid", 1);          // -Dgrid=4: the SPEC's scaling scene, as raycast --grid 4
            if (grid > 1) mesh = cl.loadClass("org.kdtree.generate.MeshGrid").getMethod("grid", meshClass, int.class).invoke(null, mesh, grid);
            Object structure = structure(cl, args[5 + i], mesh);
            // Before the mesh was bound at build time, a query took the triangles' intersector.
            Class<?> as = cl.loadClass("org.kdtree.accel.AccelerationStructure");
            Method bound = findQuery(as);
            Object[] queryArgs = bound.getParameterCount() == 0 ? new Object[0]
                    : new Object[] {cl.loadClass("org.kdtree.accel.TriangleIntersector").getConstructor(meshClass).newInstance(mesh)};
            Method query = bound;
            Class<?> raySet = cl.loadClass("org.kdtree.measure.RaySet");
            sets[i] = args[4].equals("P") ? raySet.getMethod("primary", meshClass, int.class).invoke(null, mesh, 1024)
                    : raySet.getMethod("random", meshClass, int.class).invoke(null, mesh, 1_000_000);
            Supplier<Object> queries = () -> {
                try {
                    return query.invoke(structure, queryArgs);
                } catch (ReflectiveOperationException e) {
                    throw new IllegalStateException(e);
                }
            };
            Class<?> rayBatch = cl.loadClass("org.kdtree.measure.RayBatch");
            Class<?> accel = cl.loadClass("org.kdtree.accel.AccelerationStructure");
            // A jar whose batch takes the structure traces P through its packet query, as raycast does; older ones take queries.
            batch[i] = hasConstructor(rayBatch, int.class, accel) ? rayBatch.getConstructor(int.class, accel).newInstance(1, structure)
                    : rayBatch.getConstructor(int.class, Supplier.class).newInstance(1, queries);
            trace[i] = rayBatch.getMethod("trace", raySet);
        }
        ThreadMXBean mx = ManagementFactory.getThreadMXBean();
        double[][] ms = new double[2][runs];
        Object[] sums = new Object[2];
        for (int r = -3; r < runs; r++) {
            for (int o = 0; o < 2; o++) {
                int i = (r & 1) == 0 ? o : 1 - o;
                long t0 = mx.getCurrentThreadCpuTime();
                sums[i] = trace[i].invoke(batch[i], sets[i]);
                if (r >= 0) ms[i][r] = (mx.getCurrentThreadCpuTime() - t0) / 1e6;
            }
        }
        for (double[] t : ms) Arrays.sort(t);
        double rays = args[4].equals("P") ? 1024 * 1024 : 1_000_000;
        System.out.printf(Locale.ROOT, "%s %s/%s: old %.2f Mrays/s (q3 %.2f) %s, new %.2f (q3 %.2f) %s, new/old speed %.3f%n",
                args[4], args[5], args[6], rays / ms[0][runs / 2] / 1e3, rays / ms[0][runs / 4] / 1e3, sums[0],
                rays / ms[1][runs / 2] / 1e3, rays / ms[1][runs / 4] / 1e3, sums[1], ms[0][runs / 2] / ms[1][runs / 2]);
    }

    private static Object structure(ClassLoader cl, String spec, Object mesh) throws Exception {
        Class<?> prims = cl.loadClass("org.kdtree.shape.Primitives");
        if (spec.startsWith("bvh")) {
            Object b = cl.loadClass("org.kdtree.bvh.BvhBuilder").getConstructor().newInstance();
            if (spec.contains(":")) b = b.getClass().getMethod("width", int.class).invoke(b, Integer.parseInt(spec.substring(4)));
            return b.getClass().getMethod("build", prims).invoke(b, mesh);
        }
        Object b = cl.loadClass("org.kdtree.spec.Builders").getMethod("create", String.class).invoke(null, spec);
        return cl.loadClass("org.kdtree.kdtree.KdTreeBuilder").getMethod("build", prims).invoke(b, mesh);
    }

    /** {@return whether {@code c} has a public constructor taking {@code types}} */
    static boolean hasConstructor(Class<?> c, Class<?>... types) {
        try {
            c.getConstructor(types);
            return true;
        } catch (NoSuchMethodException e) {
            return false;
        }
    }

    /** {@return the structure's silent query method}: {@code query()} now, {@code query(Intersector)} in older jars */
    static Method findQuery(Class<?> structure) throws NoSuchMethodException {
        for (Method m : structure.getMethods())
            if (m.getName().equals("query") && (m.getParameterCount() == 0
                    || m.getParameterCount() == 1 && m.getParameterTypes()[0].getSimpleName().equals("Intersector"))) return m;
        throw new NoSuchMethodException("query");
    }
}
