package org.kdtree.bench;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.lang.reflect.Method;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Locale;

/**
 * Builds one mesh with two versions of the library in one JVM, in turn, so that both see the
 * same machine at the same moments: each jar in a class loader of its own (so each has its own
 * compiled code), builds alternating and the order swapping every round, thread CPU time
 * measured. A noisy shared machine moves a whole run; this keeps the ratio between the two.
 *
 * <pre>
 * java -cp target/benchmarks.jar org.kdtree.bench.OldAgainstNew OLD.jar NEW.jar MESH.obj RUNS BUILDER [EVENT|BINNED|fast|balanced|-] [THREADS]
 * (an old jar from before the packages by structure loads too)
 * </pre>
 * BUILDER is a registered name ({@code sah}, {@code median-plane}, ...), {@code centre-midpoint}
 * or {@code bvh}; THREADS (default 1) is given to the builder. Wall time is measured when
 * THREADS &gt; 1, thread CPU time otherwise.
 */
public final class OldAgainstNew {
    private OldAgainstNew() {
    }

    public static void main(String[] args) throws Exception {
        if (args.length < 5) {
            System.err.println("usage: OldAgainstNew OLD.jar NEW.jar MESH.obj RUNS BUILDER [EVENT|BINNED|fast]");
            System.exit(2);
        }
        int runs = Integer.parseInt(args[3]);
        int threads = args.length > 6 ? Integer.parseInt(args[6]) : 1;
        Object[] meshes = new Object[2], builders = new Object[2];
        Method[] build = new Method[2];
        for (int i = 0; i < 2; i++) {
            String[] parts = args[i].split(java.io.File.pathSeparator);   // a jar, or a class path (classes:deps.jar)
            URL[] urls = new URL[parts.length];
            for (int p = 0; p < parts.length; p++) urls[p] = Path.of(parts[p]).toUri().toURL();
            ClassLoader cl = new URLClassLoader(urls, ClassLoader.getPlatformClassLoader());
            meshes[i] = cl.loadClass("org.kdtree.io.PrimitivesReader").getMethod("read", Path.class).invoke(null, Path.of(args[2]));
            builders[i] = builder(cl, args[4], args.length > 5 ? args[5] : null);
            build[i] = builders[i].getClass().getMethod("build", cl.loadClass("org.kdtree.shape.Primitives"));   // a kd-tree's or the BVH's
            if (threads > 1) builders[i].getClass().getMethod("threads", int.class).invoke(builders[i], threads);
        }
        ThreadMXBean mx = ManagementFactory.getThreadMXBean();
        double[][] ms = new double[2][runs];
        for (int r = -3; r < runs; r++) {
            for (int o = 0; o < 2; o++) {
                int i = (r & 1) == 0 ? o : 1 - o;
                long t0 = threads > 1 ? System.nanoTime() : mx.getCurrentThreadCpuTime();
                build[i].invoke(builders[i], meshes[i]);
                long t1 = threads > 1 ? System.nanoTime() : mx.getCurrentThreadCpuTime();
                if (r >= 0) ms[i][r] = (t1 - t0) / 1e6;
            }
        }
        for (double[] t : ms) Arrays.sort(t);
        System.out.printf(Locale.ROOT, "%s %s: old median %.0f ms (q1 %.0f), new median %.0f ms (q1 %.0f), new/old %.3f%n",
                args[4], args.length > 5 ? args[5] : "", ms[0][runs / 2], ms[0][runs / 4], ms[1][runs / 2], ms[1][runs / 4],
                ms[1][runs / 2] / ms[0][runs / 2]);
    }

    /** The builder named {@code name} of the library in {@code cl}, with the SAH {@code variant} if given. */
    @SuppressWarnings({"unchecked", "rawtypes"})
    private static Object builder(ClassLoader cl, String name, String variant) throws Exception {
        Object b = name.equals("centre-midpoint")
                ? cl.loadClass("org.kdtree.examples.CentreMidpointBuilder").getConstructor().newInstance()
                : name.equals("bvh") ? cl.loadClass("org.kdtree.bvh.BvhBuilder").getConstructor().newInstance()
                : specClass(cl, "Builders").getMethod("create", String.class).invoke(null, name);
        if (variant == null || variant.equals("-")) return b;
        if (variant.equals("fast") || variant.equals("balanced")) {
            Class quality = kdtreeClass(cl, "Quality");
            b.getClass().getMethod("quality", quality).invoke(b, Enum.valueOf(quality, variant.toUpperCase(Locale.ROOT)));
        } else {
            Class algorithm = kdtreeClass(cl, "SahBuilder$Algorithm");
            b.getClass().getMethod("algorithm", algorithm).invoke(b, Enum.valueOf(algorithm, variant));
        }
        return b;
    }

    /** A class of the kd-tree's package: {@code org.kdtree.kdtree} since the packages by structure, {@code org.kdtree.build} in older jars. */
    private static Class<?> kdtreeClass(ClassLoader cl, String name) throws ClassNotFoundException {
        return movedClass(cl, "kdtree", name);
    }

    /** The registry's class: {@code org.kdtree.spec} since the packages by structure, {@code org.kdtree.build} in older jars. */
    private static Class<?> specClass(ClassLoader cl, String name) throws ClassNotFoundException {
        return movedClass(cl, "spec", name);
    }

    /** {@code org.kdtree.PKG.NAME}, or in a jar from before the packages by structure {@code org.kdtree.build.NAME}. */
    private static Class<?> movedClass(ClassLoader cl, String pkg, String name) throws ClassNotFoundException {
        try {
            return cl.loadClass("org.kdtree." + pkg + "." + name);
        } catch (ClassNotFoundException older) {
            return cl.loadClass("org.kdtree.build." + name);
        }
    }
}
