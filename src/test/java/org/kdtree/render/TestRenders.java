package org.kdtree.render;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.kdtree.accel.BruteForce;
import org.kdtree.accel.TriangleIntersector;
import org.kdtree.io.PrimitivesReader;
import org.kdtree.scene.Scene;

/** Scene loading and rendering shortcuts for the render tests. */
final class TestRenders {
    private TestRenders() {
    }

    static Scene scene(String file, int w, int h, int spp) throws IOException {
        return PrimitivesReader.readScene(Path.of("scenes", file)).withImageSize(w, h).withSamplesPerPixel(spp);
    }

    /** A scene from its JSON text, read as a user's file is (through a temporary file). */
    static Scene json(String text) throws IOException {
        Path file = Files.createTempFile("test", ".json");
        try {
            Files.writeString(file, text);
            return PrimitivesReader.readScene(file);
        } finally {
            Files.delete(file);
        }
    }

    /** Renders with brute force over the watertight triangle test (the oracle), recording per-pixel rays. */
    static RenderResult bruteForce(Scene s, int threads) {
        TriangleIntersector in = new TriangleIntersector(s.mesh());
        return Renderer.render(s, () -> new BruteForce(in), Renderer.Options.defaults().withThreads(threads).recordingPixelRays());
    }
}
