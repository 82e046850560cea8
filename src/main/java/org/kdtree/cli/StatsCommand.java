package org.kdtree.cli;

import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.function.Supplier;
import org.kdtree.accel.AccelerationStructure;
import org.kdtree.io.BundledScenes;
import org.kdtree.io.PrimitivesReader;
import org.kdtree.measure.Timing;
import org.kdtree.render.RenderJob;
import org.kdtree.shape.Primitives;
import org.kdtree.spec.BuilderSpec;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Parameters;

/** {@code stats SCENE}: build a kd-tree or a bounding volume hierarchy and print its statistics and build time. */
@Command(name = "stats", mixinStandardHelpOptions = true,
        description = "Build a kd-tree, or with -b bvh a bounding volume hierarchy, over a scene (an OBJ, 2-D or JSON scene file) "
                + "and print its statistics and build time; or load one saved earlier (--tree) and print its load time.")
final class StatsCommand implements Callable<Integer> {
    @Parameters(paramLabel = "SCENE", description = "An OBJ mesh, a .scene2d or a JSON scene file, or a bundled scene: "
            + "scenes:cornell-box (or plain cornell-box where no such file exists).")
    String scene;

    @Mixin
    BuilderOptions options = new BuilderOptions("sah");

    @Mixin
    TimedRunsOptions timed = new TimedRunsOptions(1, 0);

    @Mixin
    GridOption grid = new GridOption("OBJ only: repeat the mesh in an N x N grid on the x-z plane first (the SPEC's scaling scene uses 4).");

    @Mixin
    TreeJob treeJob = new TreeJob();

    @Override public Integer call() throws Exception {
        timed.check();
        grid.check();
        BuilderSpec spec = options.spec();
        Path sceneFile = CommandFiles.requireNotFolder("SCENE", BundledScenes.resolve(scene));
        treeJob.trees.check("SCENE", sceneFile);
        Primitives prims = grid.of(PrimitivesReader.read(sceneFile));
        if (!treeJob.trees.loads()) spec.describe();       // refuses settings the builder does not take, before building
        Supplier<TreeOptions.Obtained> obtain = treeJob.obtaining(options, spec, prims);
        Timing.Timed<TreeOptions.Obtained> build;
        String what = treeJob.trees.loads() ? "load" : "build";
        try (ProgressBar bar = treeJob.progress.bar(timed.warmup + timed.runs, what + "s")) {
            build = TreeOptions.unwrap(() -> Timing.median(timed.warmup, timed.runs,
                    (i, warmUp) -> bar.step(i, warmUp ? "warm-up " + what : "timed " + what), obtain));
        }
        AccelerationStructure built = build.value().structure();
        BuilderSpec builtWith = build.value().spec();
        treeJob.trees.save(built, builtWith, prims);
        System.out.printf(Locale.ROOT, "scene: %s (%s, %d-D)%n", scene, RenderJob.count(prims.size(), "primitive"), prims.dimension());
        System.out.printf(Locale.ROOT, "builder: %s (%s)%s%n", builtWith.builder(), builtWith.describe(),
                treeJob.trees.loads() ? ", saved in " + treeJob.trees.tree : "");
        System.out.printf(Locale.ROOT, "%s time: %.1f ms%s%n", what, build.millis(),
                timed.runs > 1 ? " (median of " + timed.runs + ", after " + timed.warmup + " warm-up)" : "");
        if (treeJob.trees.saveTree != null) System.out.printf(Locale.ROOT, "saved the tree in %s (%,d bytes)%n", treeJob.trees.saveTree,
                java.nio.file.Files.size(treeJob.trees.saveTree));
        System.out.println(built.stats().describe());
        for (String note : built.notes()) System.out.println("note: " + note);
        return 0;
    }
}
