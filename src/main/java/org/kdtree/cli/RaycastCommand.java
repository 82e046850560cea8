package org.kdtree.cli;

import java.io.BufferedReader;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.function.Supplier;
import org.kdtree.accel.AccelerationStructure;
import org.kdtree.accel.RayQuery;
import org.kdtree.accel.TreeStats;
import org.kdtree.accel.TriangleIntersector;
import org.kdtree.files.AtomicFile;
import org.kdtree.measure.RayBatch;
import org.kdtree.measure.RaySet;
import org.kdtree.measure.Timing;
import org.kdtree.shape.TriangleMesh;
import org.kdtree.spec.BuilderSpec;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * {@code raycast MESH.obj}: the ray-casting benchmark of docs/benchmark-spec.md, or, with
 * {@code --rays FILE --hits FILE}, the closest hits of a user's own rays. See docs/raycast.md.
 */
@Command(name = "raycast", mixinStandardHelpOptions = true,
        description = {"The ray-casting benchmark (docs/benchmark-spec.md), or your own rays.",
                "The benchmark prints one line:",
                "  system mesh tris build_ms nodes leaves depth",
                "  P_hits P_tsum P_mrays R_hits R_tsum R_mrays",
                "With --rays FILE --hits FILE: traces the rays of FILE, one per line as",
                "'ox oy oz dx dy dz [tmin tmax]', and writes one 't triangle' or 'miss' line",
                "per ray.",
                "The vector path (Vector API kernels): run on JDK 21 or newer with",
                "--add-modules jdk.incubator.vector (a jar built by Maven on JDK 21+, or with",
                "-Dvector.jdk=DIR naming one);",
                "stderr says which path traced ('# path: vector' or '# path: scalar')."})
final class RaycastCommand implements Callable<Integer> {
    /** The SPEC line's columns, as a comment line (docs/benchmark-spec.md, "Output"). */
    static final String COLUMNS = "# system mesh tris build_ms nodes leaves depth P_hits P_tsum P_mrays R_hits R_tsum R_mrays";

    @Parameters(paramLabel = "MESH", description = "A Wavefront OBJ mesh, or the bundled one: scenes:clustered-spheres.")
    Path mesh;

    @Mixin
    BuilderOptions options = new BuilderOptions("sah").threadsHelp("threads building the tree and tracing each ray set (the same tree and hits at any count)");

    @Mixin
    GridOption grid = new GridOption("Repeat the mesh in an N x N grid on the x-z plane first (the SPEC's scaling scene uses 4).");

    /** The builder's threads (--threads), which trace each ray set too. */
    private int threads;

    @Option(names = "--rays", paramLabel = "FILE", description = "Trace the rays of FILE instead of the benchmark sets.")
    Path raysFile;

    @Option(names = "--hits", paramLabel = "FILE", description = "Where --rays writes its hits ('-' for standard output).")
    Path hitsFile;

    @Mixin
    TimedRunsOptions timed = new TimedRunsOptions(5, 2);

    @Option(names = "--verify", paramLabel = "STRIDE",
            description = "Also trace every STRIDE-th ray of each set by brute force and compare (stderr; slow by design).")
    int verifyStride;

    @Mixin
    TreeJob treeJob = new TreeJob();

    @Override public Integer call() throws Exception {
        if ((raysFile == null) != (hitsFile == null))
            throw new IllegalArgumentException("--rays and --hits go together");
        timed.check();
        grid.check();
        BuilderSpec spec = options.spec();
        if (hitsFile != null && !hitsFile.toString().equals("-")) {
            CommandFiles.requireNotInput("--hits", hitsFile, "MESH", CommandFiles.meshFile(mesh));
            CommandFiles.requireNotInput("--hits", hitsFile, "--rays", raysFile);
            CommandFiles.requireWritable("--hits", hitsFile);
        }
        if (raysFile != null && !Files.isRegularFile(raysFile))
            throw new java.io.IOException("--rays " + raysFile + (Files.isDirectory(raysFile) ? ": is a folder, not a file" : ": no such file"));
        treeJob.trees.check("MESH", CommandFiles.meshFile(mesh), "--rays", raysFile, "--hits", hitsFile);
        if (!treeJob.trees.loads()) spec.describe();        // refuses settings the builder does not take, before the mesh is read
        TriangleMesh scene = grid.of(CommandFiles.readMesh(mesh, "raycast"));
        threads = spec.value(org.kdtree.accel.SharedSettings.THREADS);
        if (raysFile != null) return traceFile(scene, spec);
        return benchmark(scene, spec);
    }

    private int traceFile(TriangleMesh scene, BuilderSpec spec) throws Exception {
        TreeOptions.Obtained tree;
        try (ProgressBar bar = treeJob.progress.bar(1, treeJob.trees.loads() ? "loads" : "builds")) {
            bar.step(0, treeJob.trees.loads() ? "load" : "build");
            tree = TreeOptions.unwrap(treeJob.obtaining(options, spec, scene));
        }
        treeJob.trees.save(tree.structure(), tree.spec(), scene);
        RayQuery traverser = tree.structure().query();
        try (BufferedReader in = Files.newBufferedReader(raysFile, StandardCharsets.UTF_8)) {
            if (hitsFile.toString().equals("-")) RayFile.trace(in, raysFile.toString(), traverser, new PrintWriter(System.out));
            else AtomicFile.writeText(hitsFile, out -> RayFile.trace(in, raysFile.toString(), traverser, new PrintWriter(out)));
        }
        return 0;
    }

    private int benchmark(TriangleMesh scene, BuilderSpec spec) throws Exception {
        int passes = timed.warmup + timed.runs;
        Timing.Timed<TreeOptions.Obtained> build;
        Timing.Timed<RayBatch.Checksum> pr, rr;
        RaySet p, r;
        String loops;
        Supplier<TreeOptions.Obtained> obtain = treeJob.obtaining(options, spec, scene);
        try (ProgressBar bar = treeJob.progress.bar(3 * passes, "steps")) {
            build = TreeOptions.unwrap(() -> Timing.median(timed.warmup, timed.runs, steps(bar, 0, treeJob.trees.loads() ? "load" : "build"), obtain));
            p = RaySet.primary(scene, RaySet.SPEC_IMAGE);
            r = RaySet.random(scene, RaySet.SPEC_RANDOM_RAYS);
            AccelerationStructure built = build.value().structure();
            try (RayBatch batch = new RayBatch(threads, built)) {
                pr = Timing.median(timed.warmup, timed.runs, steps(bar, passes, "P rays"), () -> batch.trace(p));
                rr = Timing.median(timed.warmup, timed.runs, steps(bar, 2 * passes, "R rays"), () -> batch.trace(r));
                loops = batch.describeLoops();
            }
        }
        AccelerationStructure tree = build.value().structure();
        BuilderSpec builtWith = build.value().spec();
        treeJob.trees.save(tree, builtWith, scene);
        TreeStats st = tree.stats();
        String meshName = CommandFiles.meshFile(mesh).getFileName().toString().replaceFirst("\\.[oO][bB][jJ]$", "")
                + grid.suffix();
        System.err.println(COLUMNS);   // the SPEC line stays alone on stdout, for scripts; its columns named beside it
        System.out.println(String.format(Locale.ROOT, "kdtree-%s %s %d %.1f %d %d %d %d %.6f %.3f %d %.6f %.3f",
                builtWith.builder(), meshName, scene.size(), build.millis(), st.nodes(), st.leaves(), st.maxDepth(),
                pr.value().hits(), pr.value().tSum(), p.size() / pr.seconds() / 1e6,
                rr.value().hits(), rr.value().tSum(), r.size() / rr.seconds() / 1e6));
        if (treeJob.trees.loads())
            System.err.println("# build_ms is the time to load the tree saved in " + treeJob.trees.tree + " (fingerprint and checks included),"
                    + " not to build it");
        System.err.println(String.format(Locale.ROOT, "# %s, %d thread(s); references per non-empty leaf %.2f",
                builtWith.describe(), threads, st.averageRefsPerLeaf()));
        // Which structure, loops and path traced: the BVH's vector traversal when the JVM has the Vector API, else the Java 17 one.
        System.err.println("# structure: " + tree.kind() + " (" + builtWith.builder() + ")");
        System.err.println("# loops: " + loops);
        System.err.println("# path: " + tree.describePath());
        if (verifyStride > 0) {
            BruteCheck check = new BruteCheck(new TriangleIntersector(scene), tree, verifyStride, threads);
            System.err.println("# verify P: " + check.compare(p));
            System.err.println("# verify R: " + check.compare(r));
        }
        return 0;
    }

    /** Moves {@code bar} before each run of a measurement whose first run is step {@code first}. */
    private static Timing.Progress steps(ProgressBar bar, int first, String name) {
        return (i, warmUp) -> bar.step(first + i, name + (warmUp ? " (warm-up)" : ""));
    }
}
