package org.kdtree.bench;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.lang.reflect.Method;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Locale;
import java.util.function.BooleanSupplier;
import java.util.function.Supplier;

/**
 * Renders one scene with two versions of the library (or two structures of one) in one JVM, in
 * turn, as {@link RaysOldAgainstNew} traces: each jar in a class loader of its own, renders
 * alternating and the order swapping every round, on one render thread whose CPU time is
 * measured (from the first tile's start to the last tile's end, read through the renderer's
 * stop condition, which the render thread asks before every tile and once after the last). A
 * single {@code render} command is mostly JIT warm-up; this times the renders after it.
 *
 * <pre>
 * java -cp target/benchmarks.jar org.kdtree.bench.RenderOldAgainstNew OLD.jar NEW.jar SCENE.json RUNS OLD_BUILDER NEW_BUILDER [WIDTHxHEIGHT]
 * </pre>
 * A BUILDER is {@code sah} (the exact kd-tree), {@code bvh}, {@code bvh:W} (the BVH, W wide) or
 * {@code bvh:W:L} (and leaves of at most L primitives, as {@code --leaf-size L}). Prints
 * each side's median and first quartile in ms, its rays by kind, and old/new (above 1: the new
 * renders faster).
 */
public final class RenderOldAgainstNew {
    private RenderOldAgainstNew() {
    }

    public static void main(String[] args) throws Exception {
        if (args.length < 6) {
            System.err.println("usage: RenderOldAgainstNew OLD.jar NEW.jar SCENE.json RUNS OLD_BUILDER NEW_BUILDER [WIDTHxHEIGHT]");
            System.exit(2);
        }
        int runs = Integer.parseInt(args[3]);
        ThreadMXBean mx = ManagementFactory.getThreadMXBean();
        long[] first = new long[1], last = new long[1];
        BooleanSupplier clock = () -> {
            long now = mx.getCurrentThreadCpuTime();
            if (first[0] < 0) first[0] = now;
            last[0] = now;
            return false;
        };
        Method[] render = new Method[2], rays = new Method[2];
        // Per jar: its scene, what its renderer traces (a supplier of queries, or the structure), its options.
        Object[] scenes = new Object[2], queries = new Object[2], options = new Object[2];
        for (int i = 0; i < 2; i++) {
            ClassLoader cl = new URLClassLoader(new URL[] {Path.of(args[i]).toUri().toURL()}, ClassLoader.getPlatformClassLoader());
            Object scene = readScene(cl, Path.of(args[2]));
            if (args.length > 6) {
                String[] wh = args[6].split("x");
                scene = scene.getClass().getMethod("withImageSize", int.class, int.class)
                        .invoke(scene, Integer.parseInt(wh[0]), Integer.parseInt(wh[1]));
            }
            scenes[i] = scene;
            Object mesh = scene.getClass().getMethod("mesh").invoke(scene);
            Object structure = structure(cl, args[4 + i], mesh);
            Class<?> meshClass = cl.loadClass("org.kdtree.shape.TriangleMesh");
            // Before the mesh was bound at build time, a query took the triangles' intersector.
            Method query = RaysOldAgainstNew.findQuery(cl.loadClass("org.kdtree.accel.AccelerationStructure"));
            Object[] queryArgs = query.getParameterCount() == 0 ? new Object[0]
                    : new Object[] {cl.loadClass("org.kdtree.accel.TriangleIntersector").getConstructor(meshClass).newInstance(mesh)};
            queries[i] = (Supplier<Object>) () -> {
                try {
                    return query.invoke(structure, queryArgs);
                } catch (ReflectiveOperationException e) {
                    throw new IllegalStateException(e);
                }
            };
            Class<?> renderer = cl.loadClass("org.kdtree.render.Renderer");
            Class<?> opts = cl.loadClass("org.kdtree.render.Renderer$Options");
            Object o = opts.getMethod("defaults").invoke(null);
            o = opts.getMethod("withThreads", int.class).invoke(o, 1);
            options[i] = opts.getMethod("withStop", BooleanSupplier.class).invoke(o, clock);
            // A jar whose renderer takes the structure picks its tracer from the structure's packets, as render does; older ones take queries.
            Class<?> sceneClass = cl.loadClass("org.kdtree.scene.Scene"), accel = cl.loadClass("org.kdtree.accel.AccelerationStructure");
            boolean takesStructure = Arrays.stream(renderer.getMethods()).anyMatch(m -> m.getName().equals("render")
                    && Arrays.equals(m.getParameterTypes(), new Class<?>[] {sceneClass, accel, opts}));
            render[i] = takesStructure ? renderer.getMethod("render", sceneClass, accel, opts) : renderer.getMethod("render", sceneClass, Supplier.class, opts);
            if (takesStructure) queries[i] = structure;
            rays[i] = cl.loadClass("org.kdtree.render.RenderResult").getMethod("rays");
        }
        double[][] ms = new double[2][runs];
        String[] counted = new String[2];
        for (int r = -3; r < runs; r++) {
            for (int o = 0; o < 2; o++) {
                int i = (r & 1) == 0 ? o : 1 - o;
                first[0] = -1;
                Object result = render[i].invoke(null, scenes[i], queries[i], options[i]);
                if (r >= 0) ms[i][r] = (last[0] - first[0]) / 1e6;
                counted[i] = rays[i].invoke(result).toString().replaceAll("\\s+", " ");
            }
        }
        for (double[] t : ms) Arrays.sort(t);
        System.out.printf(Locale.ROOT, "%s %s/%s: old %.0f ms (q1 %.0f) [%s], new %.0f ms (q1 %.0f) [%s], old/new speed %.3f%n",
                Path.of(args[2]).getFileName(), args[4], args[5], ms[0][runs / 2], ms[0][runs / 4], counted[0],
                ms[1][runs / 2], ms[1][runs / 4], counted[1], ms[0][runs / 2] / ms[1][runs / 2]);
    }

    private static Object structure(ClassLoader cl, String spec, Object mesh) throws Exception {
        Class<?> prims = cl.loadClass("org.kdtree.shape.Primitives");
        if (spec.startsWith("bvh")) {
            Object b = cl.loadClass("org.kdtree.bvh.BvhBuilder").getConstructor().newInstance();
            String[] parts = spec.split(":");
            if (parts.length > 1) b = b.getClass().getMethod("width", int.class).invoke(b, Integer.parseInt(parts[1]));
            if (parts.length > 2) b = b.getClass().getMethod("leafSize", int.class).invoke(b, Integer.parseInt(parts[2]));
            return b.getClass().getMethod("build", prims).invoke(b, mesh);
        }
        Object b = cl.loadClass("org.kdtree.spec.Builders").getMethod("create", String.class).invoke(null, spec);
        return cl.loadClass("org.kdtree.kdtree.KdTreeBuilder").getMethod("build", prims).invoke(b, mesh);
    }

    /** A render scene read by the jar's own reader: {@code PrimitivesReader.readScene} now, {@code SceneReader.read} in older jars. */
    private static Object readScene(ClassLoader cl, Path file) throws ReflectiveOperationException {
        try {
            return cl.loadClass("org.kdtree.io.PrimitivesReader").getMethod("readScene", Path.class).invoke(null, file);
        } catch (NoSuchMethodException older) {
            return cl.loadClass("org.kdtree.io.SceneReader").getMethod("read", Path.class).invoke(null, file);
        }
    }
}
