package org.kdtree.render;

import org.kdtree.scene.Scene;
import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.kdtree.build.Builders;
import org.kdtree.traverse.BruteForce;
import org.kdtree.traverse.TriangleIntersector;

/** The tree changes speed, never the picture: the same pixels with every builder, thread count, and brute force. */
class SameImageTest {
    static Scene cornell;
    static RenderResult reference;

    @BeforeAll static void renderReference() throws Exception {
        cornell = TestRenders.scene("cornell-box.json", 40, 40, 2);
        reference = RenderJob.run(cornell, Builders.create("sah"), Renderer.Options.defaults().withThreads(1)).result();
        assertThat(reference.image().hasInvalidPixels()).isFalse();
    }

    @ParameterizedTest
    @ValueSource(strings = {"sah", "median-plane", "object-median"})
    void everyBuilderGivesTheSameImagePixelForPixel(String builder) {
        RenderResult r = RenderJob.run(cornell, Builders.create(builder), Renderer.Options.defaults().withThreads(2)).result();
        assertSamePixels(r, reference);
        assertThat(r.rays().toString()).isEqualTo(reference.rays().toString());
    }

    @Test void threadCountDoesNotChangeTheImage() {
        RenderResult r = RenderJob.run(cornell, Builders.create("sah"), Renderer.Options.defaults().withThreads(3)).result();
        assertSamePixels(r, reference);
    }

    @Test void bruteForceOracleGivesTheSameImage() {
        TriangleIntersector in = new TriangleIntersector(cornell.mesh());
        RenderResult r = Renderer.render(cornell, () -> new BruteForce(in), Renderer.Options.defaults().withThreads(2));
        assertSamePixels(r, reference);
    }

    static void assertSamePixels(RenderResult a, RenderResult b) {
        Image x = a.image(), y = b.image();
        for (int j = 0; j < x.height(); j++)
            for (int i = 0; i < x.width(); i++)
                for (int c = 0; c < 3; c++)
                    assertThat(x.get(i, j, c)).as("pixel %d,%d channel %d", i, j, c).isEqualTo(y.get(i, j, c));
    }
}
