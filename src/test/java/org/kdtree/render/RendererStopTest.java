package org.kdtree.render;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;
import org.kdtree.kdtree.SahBuilder;
import org.kdtree.scene.Scene;

/** The workbench's Stop and progress, through the one renderer: a stopped render keeps the tiles it finished. */
class RendererStopTest {
    @Test void aStopEndsTheRenderAfterTheTilesUnderWayAndSaysSo() throws Exception {
        Scene s = TestRenders.scene("cornell-box.json", 64, 64, 1);      // 16 tiles of 16 x 16
        AtomicInteger reported = new AtomicInteger();
        Renderer.Options o = Renderer.Options.defaults().withThreads(1)
                .withProgress((done, total, image) -> {
                    reported.set(done);
                    assertThat(total).isEqualTo(16);
                    assertThat(image.width()).isEqualTo(64);
                })
                .withStop(() -> reported.get() >= 3);
        RenderJob job = RenderJob.run(s, new SahBuilder(), o);
        assertThat(job.result().stopped()).isTrue();
        assertThat(reported.get()).isEqualTo(3);
        assertThat(job.summary()).contains("(stopped before the last tile)");

        RenderJob whole = RenderJob.run(s, new SahBuilder(), Renderer.Options.defaults().withThreads(1));
        assertThat(whole.result().stopped()).isFalse();
        assertThat(whole.summary()).doesNotContain("stopped");
    }
}
