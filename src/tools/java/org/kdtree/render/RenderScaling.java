package org.kdtree.render;

import java.nio.file.Path;
import java.util.Arrays;
import java.util.Locale;
import org.kdtree.accel.TriangleIntersector;
import org.kdtree.io.PrimitivesReader;
import org.kdtree.kdtree.KdTree;
import org.kdtree.kdtree.Traverser;
import org.kdtree.scene.Scene;
import org.kdtree.spec.Builders;

/**
 * Render time against thread count on one scene: the tree is built once, a small render warms
 * up the JIT, then full renders alternate between the thread counts and the median of each is
 * reported with its speed-up over the first. Not a test: compiled with {@code mvn -Ptools test-compile},
 * run on a quiet machine (docs/rendering.md).
 *
 * <p>Arguments: SCENE [runs per count, default 3] [thread counts, default "1,2"] [WIDTHxHEIGHT] [spp].
 */
public final class RenderScaling {
    public static void main(String[] args) throws Exception {
        Scene scene = PrimitivesReader.readScene(Path.of(args.length > 0 ? args[0] : "scenes/sphereflake.json"));
        int runs = args.length > 1 ? Integer.parseInt(args[1]) : 3;
        int[] counts = Arrays.stream((args.length > 2 ? args[2] : "1,2").split(",")).mapToInt(Integer::parseInt).toArray();
        if (args.length > 3) {
            String[] wh = args[3].split("x");
            scene = scene.withImageSize(Integer.parseInt(wh[0]), Integer.parseInt(wh[1]));
        }
        if (args.length > 4) scene = scene.withSamplesPerPixel(Integer.parseInt(args[4]));
        long t0 = System.nanoTime();
        KdTree tree = Builders.create("sah").build(scene.mesh());
        System.out.printf(Locale.ROOT, "%s: %d triangles, %d x %d, %d spp, sah build %.1f s%n", scene.name(),
                scene.mesh().size(), scene.camera().width(), scene.camera().height(), scene.samplesPerPixel(),
                (System.nanoTime() - t0) / 1e9);
        Renderer.render(scene.withImageSize(160, 120), () -> new Traverser(tree), Renderer.Options.defaults());
        double[][] seconds = new double[counts.length][runs];
        final Scene timed = scene;
        for (int r = 0; r < runs; r++) {
            for (int c = 0; c < counts.length; c++) {
                RenderResult res = Renderer.render(timed, () -> new Traverser(tree),
                        Renderer.Options.defaults().withThreads(counts[c]));
                seconds[c][r] = res.renderNanos() / 1e9;
            }
        }
        double base = 0;
        for (int c = 0; c < counts.length; c++) {
            Arrays.sort(seconds[c]);
            double median = seconds[c][runs / 2];
            if (c == 0) base = median;
            System.out.printf(Locale.ROOT, "%d threads: median render %.3f s of %s, speed-up %.2f%n", counts[c], median,
                    Arrays.toString(seconds[c]), base / median);
        }
    }
}
