package org.kdtree.cli;

import java.nio.file.Path;
import java.util.concurrent.Callable;
import org.kdtree.io.SceneFile;
import org.kdtree.render.RenderJob;
import org.kdtree.render.Renderer;
import org.kdtree.render.Scene;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/** {@code render SCENE -o out.png}: build a kd-tree over a JSON scene, ray trace it, write a PNG. */
@Command(name = "render", mixinStandardHelpOptions = true,
        description = "Ray trace a JSON scene (docs/scene-format.md) to a PNG, simulating only the effects it calls for, "
                + "and print the effects, rays by kind, times and tree statistics.")
public final class RenderCommand implements Callable<Integer> {
    @Parameters(paramLabel = "SCENE", description = "A JSON scene file, e.g. scenes/cornell-box.json.")
    Path scene;

    @Option(names = {"-o", "--output"}, defaultValue = "render.png", description = "PNG file to write (default: ${DEFAULT-VALUE}).")
    Path output;

    @Mixin
    BuilderOptions options;

    @Option(names = "--threads", description = "Render threads (default: all cores).")
    Integer threads;

    @Option(names = "--spp", description = "Samples per pixel (default: the scene's).")
    Integer spp;

    @Option(names = "--ray-depth", description = "Maximum reflection/refraction depth (default: the scene's maxDepth; "
            + "--max-depth is the tree's).")
    Integer rayDepth;

    @Option(names = "--width", description = "Image width (default: the scene's).")
    Integer width;

    @Option(names = "--height", description = "Image height (default: the scene's).")
    Integer height;

    @Option(names = {"-q", "--quiet"}, description = "No progress bar.")
    boolean quiet;

    @Override public Integer call() throws Exception {
        Scene s = SceneFile.read(scene);
        if (spp != null) {
            if (spp < 1) throw new IllegalArgumentException("--spp must be at least 1");
            s = s.withSamplesPerPixel(spp);
        }
        if (rayDepth != null) {
            if (rayDepth < 0) throw new IllegalArgumentException("--ray-depth must be at least 0");
            s = s.withMaxDepth(rayDepth);
        }
        if (width != null || height != null) {
            int w = width != null ? width : s.camera().width(), h = height != null ? height : s.camera().height();
            if (w < 1 || h < 1) throw new IllegalArgumentException("--width and --height must be at least 1");
            s = s.withImageSize(w, h);
        }
        Renderer.Options o = Renderer.Options.defaults();
        if (threads != null) {
            if (threads < 1) throw new IllegalArgumentException("--threads must be at least 1");
            o = o.withThreads(threads);
        }
        if (!quiet) o = o.withProgress(System.err);
        RenderJob job = RenderJob.run(s, options.create(), o);
        job.result().image().writePng(output);
        System.out.print(job.summary());
        System.out.println("wrote " + output);
        return 0;
    }
}
