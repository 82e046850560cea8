package org.kdtree.cli;

import java.nio.file.Path;
import java.util.concurrent.Callable;
import org.kdtree.accel.SharedSettings;
import org.kdtree.io.BundledScenes;
import org.kdtree.io.FileKind;
import org.kdtree.io.PrimitivesReader;
import org.kdtree.limits.Limits;
import org.kdtree.render.RenderJob;
import org.kdtree.render.Renderer;
import org.kdtree.scene.Scene;
import org.kdtree.spec.BuilderSpec;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/** {@code render SCENE -o out.png}: build a kd-tree (or a BVH) over a JSON scene, ray trace it, write a PNG. */
@Command(name = "render", mixinStandardHelpOptions = true,
        description = "Ray trace a JSON scene (docs/scene-format.md), or a bare OBJ mesh framed with a default camera and light, to a PNG, simulating only the effects it calls for, "
                + "and print the effects, rays by kind, times and tree statistics. --threads also renders "
                + "(without it: the tree on one thread, the image on all cores).")
final class RenderCommand implements Callable<Integer> {
    @Parameters(paramLabel = "SCENE", description = "A JSON scene file, e.g. scenes/cornell-box.json, a bundled "
            + "scene from any folder (scenes:cornell-box), or an OBJ mesh (framed and lit for you).")
    String scene;

    @Option(paramLabel = "FILE", names = {"-o", "--output"}, defaultValue = "render.png", description = "PNG file to write (default: ${DEFAULT-VALUE}).")
    Path output;

    @Mixin
    BuilderOptions options = new BuilderOptions("sah");

    @Option(paramLabel = "N", names = "--spp", description = "Samples per pixel (default: the scene's).")
    Integer spp;

    @Option(paramLabel = "N", names = "--ray-depth", description = "Maximum reflection/refraction depth (default: the scene's maxDepth; "
            + "--max-depth is the tree's).")
    Integer rayDepth;

    @Option(paramLabel = "N", names = "--width", description = "Image width (default: the scene's).")
    Integer width;

    @Option(paramLabel = "N", names = "--height", description = "Image height (default: the scene's).")
    Integer height;

    @Option(names = "--blocks", description = "Trace 8 x 8 pixels at a time, their rays in packets through the structure's packet "
            + "loop, even where that is slower than one pixel at a time (as it is today for both structures): to measure it; "
            + "the same image.")
    boolean blocks;

    @Mixin
    TreeJob treeJob = new TreeJob();

    @Override public Integer call() throws Exception {
        checkOutput();
        Path sceneFile = BundledScenes.resolve(scene);
        requireRenderable(sceneFile);
        CommandFiles.requireNotInput("-o", output, "SCENE", sceneFile);
        treeJob.trees.check("SCENE", sceneFile, "-o", output);
        Scene s = PrimitivesReader.readScene(sceneFile);
        if (FileKind.of(sceneFile) == FileKind.OBJ) System.err.println("# " + scene + " is " + PrimitivesReader.BARE_MESH);
        if (spp != null) s = s.withSamplesPerPixel(Limits.SAMPLES_PER_PIXEL.check("--spp", spp));
        if (rayDepth != null) s = s.withMaxDepth(Limits.RAY_DEPTH.check("--ray-depth", rayDepth));
        if (width != null || height != null) {
            int w = width != null ? Limits.IMAGE_SIDE.check("--width", width) : s.camera().width();
            int h = height != null ? Limits.IMAGE_SIDE.check("--height", height) : s.camera().height();
            s = s.withImageSize(w, h);
        }
        BuilderSpec spec = options.spec();
        Renderer.Options o = Renderer.Options.defaults();
        if (spec.get(SharedSettings.THREADS) != null) o = o.withThreads(spec.get(SharedSettings.THREADS));
        if (blocks) o = o.inBlocks();
        RenderJob job;
        if (!treeJob.progress.quiet) System.out.printf(java.util.Locale.ROOT, "rendering %s: %d x %d, %d sample%s per pixel, into %s%n", scene,
                s.camera().width(), s.camera().height(), s.samplesPerPixel(), s.samplesPerPixel() == 1 ? "" : "s", output);
        try (ProgressBar bar = treeJob.progress.bar(1, "tiles")) {
            Scene sc = s;
            Renderer.Options withProgress = o.withProgress((done, total, image) -> bar.update(done, total));
            java.util.function.Supplier<TreeOptions.Obtained> obtain = treeJob.obtaining(options, spec, s.mesh());
            TreeOptions.Obtained[] made = new TreeOptions.Obtained[1];
            String who = treeJob.trees.loads() ? "loaded from " + treeJob.trees.tree + ", not built" : spec.builder();
            job = TreeOptions.unwrap(() -> RenderJob.run(sc, who, () -> (made[0] = obtain.get()).structure(), withProgress));
            treeJob.trees.save(made[0].structure(), made[0].spec(), sc.mesh());
        }
        job.result().image().writePng(output);
        if (!treeJob.progress.quiet) {     // which structure, tracer and loop, and which path, as raycast says them
            System.err.println("# structure: " + job.structure().kind() + " (" + job.builderName() + ")");
            System.err.println("# tracer: " + job.result().tracer());
            System.err.println("# path: " + job.structure().describePath());
        }
        System.out.print(job.summary());
        System.out.println("wrote " + output);
        return 0;
    }

    /** The bundled scenes render takes: the JSON ones. */
    private static String jsonScenes() {
        return String.join(", ", BundledScenes.FILES.stream().filter(f -> FileKind.of(f) == FileKind.JSON)
                .map(f -> BundledScenes.PREFIX + f.substring(0, f.length() - FileKind.JSON.extension().length())).toList());
    }

    /** Refuses a SCENE that is neither a JSON scene nor an OBJ mesh, naming it as the user gave it and saying what render takes. */
    private void requireRenderable(Path sceneFile) {
        FileKind kind = FileKind.of(sceneFile);
        if ((kind == FileKind.OBJ || kind != null && kind.renders()) && !java.nio.file.Files.isDirectory(sceneFile)) return;
        if (!java.nio.file.Files.exists(sceneFile)) return; // the reader names a missing file, whatever its name
        String what;
        if (java.nio.file.Files.isDirectory(sceneFile)) what = "is a folder, not a file";
        else if (kind == FileKind.SCENE2D) what = "is a 2-D scene; open it in the workbench (gui) or give it to stats";
        else what = "is neither a JSON scene (.json) nor an OBJ mesh (.obj)";
        throw new IllegalArgumentException("SCENE " + scene + ": " + what + ". render takes a JSON scene (camera, lights, materials, "
                + "objects: docs/scene-format.md), such as " + jsonScenes() + ", or an OBJ mesh, which it frames and lights");
    }

    /** Refuses, before any rendering, an output the image could not be written to. */
    private void checkOutput() {
        if (java.nio.file.Files.isDirectory(output))
            throw new IllegalArgumentException("-o " + output + ": is a folder; give a file name such as " + output.resolve("render.png"));
        if (!output.getFileName().toString().toLowerCase(java.util.Locale.ROOT).endsWith(".png"))
            throw new IllegalArgumentException("-o " + output + ": the image is written as PNG; give a file name ending in .png");
        CommandFiles.requireWritable("-o", output);
    }
}
