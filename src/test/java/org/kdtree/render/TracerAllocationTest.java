package org.kdtree.render;

import static org.assertj.core.api.Assertions.assertThat;

import java.lang.management.ManagementFactory;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.kdtree.bvh.BvhBuilder;
import org.kdtree.kdtree.Traverser;
import org.kdtree.scene.Scene;
import org.kdtree.spec.Builders;

/**
 * The tracer allocates nothing per ray, nor per pixel: over a Cornell box with glass, a mirror and
 * an area light (camera, shadow, reflection and refraction rays), one pixel at a time through the
 * kd-tree and in 8 x 8 blocks with packets through the BVH, the bytes this thread allocates stay
 * below a few kilobytes for the whole image (the random streams are a long each, not an object
 * per pixel).
 */
class TracerAllocationTest {
    @Test void tracingAllocatesNothingPerPixel() throws Exception {
        Scene scene = TestRenders.scene("cornell-box.json", 32, 32, 4);
        Tracer tracer = new Tracer(scene, new EffectPlan(scene),
                new Traverser(Builders.create("sah").build(scene.mesh())));
        double[] rgb = new double[3];
        assertAllocatesLittle(tracer, () -> {
            for (int y = 0; y < 32; y++) for (int x = 0; x < 32; x++) tracer.pixel(x, y, rgb);
        });
    }

    @Test void blocksWithPacketsAllocateNothingPerPixel() throws Exception {
        Scene scene = TestRenders.scene("cornell-box.json", 32, 32, 4);
        var bvh = new BvhBuilder().build(scene.mesh());
        Tracer tracer = new Tracer(scene, new EffectPlan(scene), bvh.query(), bvh.packetQuery(), Tracer.SHADOW_BUDGET, true);
        assertThat(tracer.tracesPackets()).isTrue();
        double[] rgb = new double[3];
        assertAllocatesLittle(tracer, () -> {
            for (int y = 0; y < 32; y += 8)
                for (int x = 0; x < 32; x += 8) {
                    tracer.block(x, y, x + 8, y + 8);
                    for (int i = 0; i < 64; i++) tracer.blockColour(i, rgb);
                }
        });
    }

    private static void assertAllocatesLittle(Tracer tracer, Runnable render) {
        var threads = ManagementFactory.getThreadMXBean();
        Assumptions.assumeTrue(threads instanceof com.sun.management.ThreadMXBean, "needs allocation counting");
        var counting = (com.sun.management.ThreadMXBean) threads;
        render.run();                              // first touches: class loading, lazily built tables
        // The vector path's vectors are objects until C2 compiles its loops (then scalar-replaced):
        // renders are repeated until the JIT has, and the least a render allocated is what counts.
        long bytes = Long.MAX_VALUE, rays = 0;
        for (int run = 0; run < 40 && bytes >= 4096; run++) {
            long r0 = tracer.counts().total();
            long before = counting.getThreadAllocatedBytes(Thread.currentThread().getId());
            render.run();
            bytes = Math.min(bytes, counting.getThreadAllocatedBytes(Thread.currentThread().getId()) - before);
            rays = tracer.counts().total() - r0;
        }
        assertThat(rays).isGreaterThan(50_000);
        assertThat(bytes).as("bytes allocated for %d rays over %d pixels", rays, 32 * 32).isLessThan(4096L);
    }
}
