package org.kdtree.render;

import java.io.IOException;
import java.io.StringReader;
import java.nio.file.Path;
import org.kdtree.accel.BruteForce;
import org.kdtree.accel.TriangleIntersector;
import org.kdtree.io.SceneReader;
import org.kdtree.scene.Scene;

/** Scene loading and rendering shortcuts for the render tests. */
final class TestRenders {
    private TestRenders() {
    }

    static Scene scene(String file, int w, int h, int spp) throws IOException {
        return SceneReader.read(Path.of("scenes", file)).withImageSize(w, h).withSamplesPerPixel(spp);
    }

    static Scene json(String text) throws IOException {
        return SceneReader.read(new StringReader(text), "test.json", Path.of("."));
    }

    /** Renders with brute force over the watertight triangle test (the oracle), recording per-pixel rays. */
    static RenderResult bruteForce(Scene s, int threads) {
        TriangleIntersector in = new TriangleIntersector(s.mesh());
        return Renderer.render(s, () -> new BruteForce(in), Renderer.Options.defaults().withThreads(threads).recordingPixelRays());
    }
}
