package org.kdtree.cli;

import java.io.BufferedReader;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.kdtree.build.KdTreeBuilder;
import org.kdtree.shape.ProceduralScenes;
import org.kdtree.shape.TriangleMesh;
import org.kdtree.traverse.Traverser;
import org.kdtree.traverse.TriangleIntersector;
import org.kdtree.tree.KdTree;
import org.kdtree.tree.TreeStats;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import org.kdtree.tradeoff.RaySet;

/**
 * {@code raycast MESH.obj}: the ray-casting benchmark of bench/SPEC.md, or, with
 * {@code --rays FILE --hits FILE}, the closest hits of a user's own rays. See docs/raycast.md.
 */
@Command(name = "raycast", mixinStandardHelpOptions = true,
        description = {"Ray-casting benchmark of the shared spec (bench/SPEC.md), or trace your own rays. Prints one line:",
                "  system mesh tris build_ms nodes leaves depth",
                "  P_hits P_tsum P_mrays R_hits R_tsum R_mrays",
                "With --rays FILE --hits FILE: traces the rays of FILE, one per line as",
                "'ox oy oz dx dy dz [tmin tmax]', and writes one 't triangle' or 'miss' line",
                "per ray."})
public final class RaycastCommand implements Callable<Integer> {
    @Parameters(paramLabel = "MESH", description = "A Wavefront OBJ mesh.")
    Path mesh;

    @Mixin
    BuilderOptions options;

    @Option(names = "--grid", defaultValue = "1", paramLabel = "N",
            description = "Repeat the mesh in an N x N grid on the x-z plane first (the SPEC's scaling scene uses 4).")
    int grid;

    @Option(names = "--threads", defaultValue = "1", paramLabel = "T",
            description = "Threads building the tree and tracing each ray set (default: ${DEFAULT-VALUE}).")
    int threads;

    @Option(names = "--rays", paramLabel = "FILE", description = "Trace the rays of FILE instead of the benchmark sets.")
    Path raysFile;

    @Option(names = "--hits", paramLabel = "FILE", description = "Where --rays writes its hits ('-' for standard output).")
    Path hitsFile;

    @Option(names = "--runs", defaultValue = "5", description = "Timed runs; the median is reported (default: ${DEFAULT-VALUE}).")
    int runs;

    @Option(names = "--warmup", defaultValue = "2", description = "Untimed runs first (default: ${DEFAULT-VALUE}).")
    int warmup;

    @Option(names = "--verify", hidden = true, paramLabel = "STRIDE",
            description = "Also trace every STRIDE-th ray of each set by brute force and compare (stderr).")
    int verifyStride;

    @Override public Integer call() throws Exception {
        if ((raysFile == null) != (hitsFile == null))
            throw new IllegalArgumentException("--rays and --hits go together");
        if (runs < 1 || warmup < 0) throw new IllegalArgumentException("--runs must be >= 1 and --warmup >= 0");
        TriangleMesh scene = ProceduralScenes.grid(CommandFiles.readMesh(mesh, "raycast"), grid);
        KdTreeBuilder builder = options.create().threads(threads);
        if (raysFile != null) return traceFile(scene, builder);
        return benchmark(scene, builder);
    }

    private int traceFile(TriangleMesh scene, KdTreeBuilder builder) throws Exception {
        KdTree tree = builder.build(scene);
        Traverser traverser = new Traverser(tree, new TriangleIntersector(scene));
        if (!Files.isRegularFile(raysFile)) throw new java.io.IOException(raysFile + ": no such file");
        if (!hitsFile.toString().equals("-")) CommandFiles.requireFolder("--hits", hitsFile);
        try (BufferedReader in = Files.newBufferedReader(raysFile, StandardCharsets.UTF_8);
             PrintWriter out = hitsFile.toString().equals("-") ? new PrintWriter(System.out)
                     : new PrintWriter(Files.newBufferedWriter(hitsFile, StandardCharsets.UTF_8))) {
            RayFile.trace(in, raysFile.toString(), traverser, out);
        }
        return 0;
    }

    private int benchmark(TriangleMesh scene, KdTreeBuilder builder) throws Exception {
        double[] ms = new double[runs];
        KdTree tree = null;
        for (int i = 0; i < warmup + runs; i++) {
            long t0 = System.nanoTime();
            tree = builder.build(scene);
            if (i >= warmup) ms[i - warmup] = (System.nanoTime() - t0) / 1e6;
        }
        TreeStats st = tree.stats();
        var box = ProceduralScenes.vertexBounds(scene);
        RaySet p = RaySet.primary(box, RaySet.SPEC_IMAGE), r = RaySet.random(box, RaySet.SPEC_RANDOM_RAYS);
        TriangleIntersector tris = new TriangleIntersector(scene);
        KdTree built = tree;
        RayBatch.Result pr, rr;
        try (RayBatch batch = new RayBatch(threads, () -> new Traverser(built, tris))) {
            pr = median(batch, p);
            rr = median(batch, r);
        }
        String meshName = mesh.getFileName().toString().replaceFirst("\\.[oO][bB][jJ]$", "")
                + (grid > 1 ? "-grid" + grid : "");
        System.out.println(String.format(Locale.ROOT, "kdtree-%s %s %d %.1f %d %d %d %d %.6f %.3f %d %.6f %.3f",
                builder.name(), meshName, scene.size(), median(ms), st.nodes(), st.leaves(), st.maxDepth(),
                pr.hits(), pr.tSum(), p.size() / pr.seconds() / 1e6, rr.hits(), rr.tSum(), r.size() / rr.seconds() / 1e6));
        System.err.println(String.format(Locale.ROOT, "# %s, %d thread(s); references per non-empty leaf %.2f",
                builder.describeSettings(), threads, st.averageRefsPerLeaf()));
        if (verifyStride > 0) {
            BruteCheck check = new BruteCheck(tris, new Traverser(tree, tris), verifyStride, threads);
            System.err.println("# verify P: " + check.compare(p));
            System.err.println("# verify R: " + check.compare(r));
        }
        return 0;
    }

    /** The run of median time among warm-up + timed runs (its checksum is that of every run). */
    private RayBatch.Result median(RayBatch batch, RaySet rays) throws Exception {
        RayBatch.Result[] res = new RayBatch.Result[runs];
        for (int i = 0; i < warmup + runs; i++) {
            RayBatch.Result x = batch.trace(rays);
            if (i >= warmup) res[i - warmup] = x;
        }
        Arrays.sort(res, (a, b) -> Double.compare(a.seconds(), b.seconds()));
        return res[runs / 2];
    }

    private static double median(double[] v) {
        double[] s = v.clone();
        Arrays.sort(s);
        return s[s.length / 2];
    }
}
