package org.kdtree.render;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;
import org.kdtree.accel.AccelerationStructure;
import org.kdtree.accel.Hit;
import org.kdtree.accel.PacketQuery;
import org.kdtree.accel.RayQuery;
import org.kdtree.accel.TriangleIntersector;
import org.kdtree.bvh.BvhBuilder;
import org.kdtree.geom.Ray;
import org.kdtree.scene.Scene;

/** Camera rays traced in packets give every pixel the colour, and the ray counts, it gets one ray at a time. */
class PacketRenderTest {
    @Test void packetsRenderTheSameImage() throws Exception {
        for (String file : new String[] {"cornell-box.json", "sphereflake.json", "obj-materials.json"}) {
            Scene s = TestRenders.scene(file, 61, 45, 1);
            TriangleIntersector tris = new TriangleIntersector(s.mesh());
            AccelerationStructure bvh = new BvhBuilder().build(s.mesh());
            assertThat(bvh.query()).isInstanceOf(PacketQuery.class);
            RenderResult packets = Renderer.render(s, () -> bvh.query(), Renderer.Options.defaults().withThreads(2).recordingPixelRays());
            RenderResult single = Renderer.render(s, () -> alone(bvh.query()), Renderer.Options.defaults().withThreads(2).recordingPixelRays());
            for (int y = 0; y < 45; y++)
                for (int x = 0; x < 61; x++)
                    for (int c = 0; c < 3; c++)
                        assertThat(packets.image().get(x, y, c)).as(file + " pixel " + x + ", " + y).isEqualTo(single.image().get(x, y, c));
            assertThat(packets.rays().toString()).isEqualTo(single.rays().toString());
            for (RayKind k : RayKind.values()) assertThat(packets.pixelRays(k, 30, 20)).isEqualTo(single.pixelRays(k, 30, 20));
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
