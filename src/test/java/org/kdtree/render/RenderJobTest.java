package org.kdtree.render;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;
import org.kdtree.scene.Scene;
import org.kdtree.spec.Builders;

/** The report after a render: counts in good English, rays by kind with one rate for them all. */
class RenderJobTest {
    @Test void countsAreSingularForOne() {
        assertThat(RenderJob.count(1, "light")).isEqualTo("1 light");
        assertThat(RenderJob.count(2, "light")).isEqualTo("2 lights");
        assertThat(RenderJob.count(0, "light")).isEqualTo("0 lights");
        assertThat(RenderJob.count(10_370, "primitive")).isEqualTo("10,370 primitives");
    }

    @Test void theRayLinesGiveEachKindAndOneRateForTheirTotal() {
        RayCounts rays = new RayCounts();
        for (int i = 0; i < 3000; i++) rays.add(RayKind.CAMERA);
        rays.add(RayKind.SHADOW);
        String lines = RenderJob.rayLines(rays, 1_000_000_000L);
        assertThat(lines).startsWith("rays:").contains("3,000").contains("3,001  (3,001 rays/s over the render time)");
        assertThat(lines.lines()).hasSize(RayKind.values().length + 2);
    }

    @Test void theSummaryOfARenderCountsItsSceneInGoodEnglish() throws Exception {
        Scene s = TestRenders.scene("cornell-box.json", 16, 12, 1);
        String summary = RenderJob.run(s, Builders.create("sah"), Renderer.Options.defaults().withThreads(1)).summary();
        assertThat(summary).contains("1 light)").contains("1 sample per pixel, 1 thread").contains("build time:")
                .contains("rays:").contains("kd-tree:");
    }

    /** Issue 45, item 5: the statistics a render shows (the workbench's too) name the structure, the tracer and its loop, and the path. */
    @Test void theSummaryNamesTheEngineThatTracedTheRender() throws Exception {
        Scene s = TestRenders.scene("cornell-box.json", 16, 12, 1);
        for (String builder : new String[] {"sah", "bvh"}) {
            RenderJob job = RenderJob.run(s, org.kdtree.spec.BuilderSpec.of(builder),
                    org.kdtree.kdtree.Supervisor.of(org.kdtree.limits.Deadlines.COMMAND_LINE), Renderer.Options.defaults().withThreads(1));
            assertThat(job.summary()).as(builder).contains("traced by: " + job.structure().kind() + ", " + job.result().tracer()
                    + "; path: " + job.structure().describePath());
        }
    }
}
