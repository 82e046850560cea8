package org.kdtree.render;

import static org.assertj.core.api.Assertions.assertThat;

import java.lang.management.ManagementFactory;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.kdtree.kdtree.Traverser;
import org.kdtree.scene.Scene;
import org.kdtree.spec.Builders;

/**
 * The tracer allocates nothing per ray: over a Cornell box with glass, a mirror and an area light
 * (camera, shadow, reflection and refraction rays), the bytes this thread allocates stay below
 * one small object per pixel (the pixel's random-number generator, which keeps images the same
 * whatever thread renders a pixel).
 */
class TracerAllocationTest {
    @Test void tracingAllocatesAtMostTheSamplerOfEachPixel() throws Exception {
        var threads = ManagementFactory.getThreadMXBean();
        Assumptions.assumeTrue(threads instanceof com.sun.management.ThreadMXBean, "needs allocation counting");
        var counting = (com.sun.management.ThreadMXBean) threads;
        Scene scene = TestRenders.scene("cornell-box.json", 32, 32, 4);
        Tracer tracer = new Tracer(scene, new EffectPlan(scene),
                new Traverser(Builders.create("sah").build(scene.mesh())));
        double[] rgb = new double[3];
        render(tracer, rgb);                       // first touches: class loading, lazily built tables
        long rays = tracer.counts().total();
        long before = counting.getThreadAllocatedBytes(Thread.currentThread().getId());
        render(tracer, rgb);
        long bytes = counting.getThreadAllocatedBytes(Thread.currentThread().getId()) - before;
        rays = tracer.counts().total() - rays;
        assertThat(rays).isGreaterThan(50_000);
        assertThat(bytes).as("bytes allocated for %d rays over %d pixels", rays, 32 * 32).isLessThan(128L * 32 * 32);
    }

    private static void render(Tracer tracer, double[] rgb) {
        for (int y = 0; y < 32; y++) for (int x = 0; x < 32; x++) tracer.pixel(x, y, rgb);
    }
}
