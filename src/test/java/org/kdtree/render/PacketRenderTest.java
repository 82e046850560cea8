package org.kdtree.render;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;
import org.kdtree.accel.AccelerationStructure;
import org.kdtree.accel.Hit;
import org.kdtree.accel.RayQuery;
import org.kdtree.accel.TriangleIntersector;
import org.kdtree.bvh.BvhBuilder;
import org.kdtree.geom.Ray;
import org.kdtree.scene.Scene;

/**
 * Pixels traced in 8 x 8 blocks, their camera rays and their shadow rays in packets, get every
 * pixel the colour, and the ray counts, that one ray at a time gives it: with one sample per
 * pixel and with several (jittered camera rays), with area, point and directional lights, with
 * reflection and refraction, on images whose sides are not multiples of 8.
 */
class PacketRenderTest {
    @Test void packetsRenderTheSameImage() throws Exception {
        for (String file : new String[] {"cornell-box.json", "sphereflake.json", "obj-materials.json", "shadows-only.json", "diffuse-only.json"})
            for (int spp : new int[] {1, 4}) {
                Scene s = TestRenders.scene(file, 61, 45, spp);
                AccelerationStructure bvh = new BvhBuilder().build(s.mesh());
                assertThat(bvh.packetQuery().tracesTogether()).isTrue();
                RenderResult packets = Renderer.render(s, bvh, Renderer.Options.defaults().withThreads(2).recordingPixelRays().inBlocks());
                assertThat(packets.tracer()).startsWith("blocks of 8 x 8 pixels");
                RenderResult single = Renderer.render(s, () -> alone(bvh.query()), Renderer.Options.defaults().withThreads(2).recordingPixelRays());
                String what = file + ", " + spp + " spp, pixel ";
                for (int y = 0; y < 45; y++)
                    for (int x = 0; x < 61; x++) {
                        for (int c = 0; c < 3; c++)
                            assertThat(packets.image().get(x, y, c)).as(what + x + ", " + y).isEqualTo(single.image().get(x, y, c));
                        for (RayKind k : RayKind.values())
                            assertThat(packets.pixelRays(k, x, y)).as(what + x + ", " + y + ", " + k).isEqualTo(single.pixelRays(k, x, y));
                    }
                assertThat(packets.rays().toString()).isEqualTo(single.rays().toString());
                assertThat(packets.rays().get(RayKind.CAMERA)).isEqualTo(61L * 45 * spp);
            }
    }

    /**
     * Past a block's budget of light samples kept aside, reflection and refraction rays are traced
     * depth first where they arise (deep trees of glass under many light samples stay small): the
     * pixels and their ray counts stay those of one ray at a time, with every secondary ray past
     * the budget (the camera rays' trees alone) and with the budget crossed mid-level.
     */
    @Test void pastTheBudgetRaysGoDepthFirstWithTheSameColours() throws Exception {
        for (String file : new String[] {"cornell-box.json", "sphereflake.json"}) {
            Scene s = TestRenders.scene(file, 24, 16, 2);
            AccelerationStructure bvh = new BvhBuilder().build(s.mesh());
            EffectPlan plan = new EffectPlan(s);
            Tracer single = new Tracer(s, plan, alone(bvh.query()));
            for (int budget : new int[] {1, 66 * 16, 72 * 16})
                sameBlocks(new Tracer(s, plan, bvh.query(), bvh.packetQuery(), budget, true), single, file + ", budget " + budget);
        }
    }

    /**
     * The kd-tree's packet loop through the block tracer (which renders choose only where it is
     * repaid: not the kd-tree's on Java 17, so the test asks for it) gives every pixel the colour
     * and the ray counts one ray at a time gives it.
     */
    @Test void theKdTreesPacketLoopRendersTheSameImage() throws Exception {
        for (String file : new String[] {"cornell-box.json", "sphereflake.json", "obj-materials.json"}) {
            Scene s = TestRenders.scene(file, 24, 16, 2);
            AccelerationStructure kd = org.kdtree.spec.Builders.create("sah").build(s.mesh());
            assertThat(kd.packetQuery().tracesTogether()).isTrue();
            EffectPlan plan = new EffectPlan(s);
            Tracer single = new Tracer(s, plan, alone(kd.query()));
            sameBlocks(new Tracer(s, plan, kd.query(), kd.packetQuery(), Tracer.SHADOW_BUDGET, true), single, file);
        }
    }

    /** The 24 x 16 image's 8 x 8 blocks through {@code packets}: each pixel's colour and rays those {@code single} gives it. */
    private static void sameBlocks(Tracer packets, Tracer single, String what) {
        assertThat(packets.tracesPackets()).isTrue();
        double[] want = new double[3], got = new double[3];
        for (int by = 0; by < 16; by += 8)
            for (int bx = 0; bx < 24; bx += 8) {
                packets.block(bx, by, bx + 8, by + 8);
                for (int i = 0; i < 64; i++) {
                    long before = single.counts().total();
                    single.pixel(bx + i % 8, by + i / 8, want);
                    packets.blockColour(i, got);
                    String pixel = what + ", pixel " + (bx + i % 8) + ", " + (by + i / 8);
                    assertThat(got).as(pixel).containsExactly(want);
                    int rays = 0;
                    for (RayKind k : RayKind.values()) rays += packets.blockRays(k, i);
                    assertThat((long) rays).as(pixel).isEqualTo(single.counts().total() - before);
                }
            }
    }

    /** The same query, without its packets. */
    private static RayQuery alone(RayQuery q) {
        return new RayQuery() {
            @Override public boolean closestHit(Ray ray, double tMin, double tMax, Hit hit) { return q.closestHit(ray, tMin, tMax, hit); }
            @Override public boolean anyHit(Ray ray, double tMin, double tMax) { return q.anyHit(ray, tMin, tMax); }
        };
    }
}
