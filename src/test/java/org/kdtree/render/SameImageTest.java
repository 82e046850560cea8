package org.kdtree.render;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;
import org.kdtree.accel.BruteForce;
import org.kdtree.accel.Hit;
import org.kdtree.accel.RayQuery;
import org.kdtree.accel.SharedSettings;
import org.kdtree.accel.TriangleIntersector;
import org.kdtree.bvh.BvhBuilder;
import org.kdtree.geom.Ray;
import org.kdtree.kdtree.Supervisor;
import org.kdtree.limits.Deadlines;
import org.kdtree.scene.Scene;
import org.kdtree.spec.BuilderSpec;
import org.kdtree.spec.Builders;

/** The tree changes speed, never the picture: the same pixels with every builder, the BVH, thread count, and brute force. */
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

    /**
     * A bounding volume hierarchy finds the same closest hits as the kd-tree, so the picture is the
     * same pixel for pixel, and so are the rays it took (jittered samples: no ray meets an edge
     * exactly, see {@link #whereTheBvhAndTheKdTreeDisagreeTheHitsAreTies}).
     */
    @ParameterizedTest(name = "bvh --bvh-width {0} --leaf-size {1}")
    @CsvSource({"4, 16", "2, 16", "8, 1"})
    void theBvhGivesTheSameImagePixelForPixel(int width, int leafSize) {
        BuilderSpec bvh = BuilderSpec.of("bvh").with(BvhBuilder.WIDTH, width).with(SharedSettings.LEAF_SIZE, leafSize);
        RenderJob job = RenderJob.run(cornell, bvh, Supervisor.of(Deadlines.COMMAND_LINE), Renderer.Options.defaults().withThreads(2));
        assertThat(job.structure().kind()).isEqualTo("bvh");
        assertThat(job.summary()).contains("build time: ").contains("(bvh)").contains("bvh:").contains("nodes: ");
        assertSamePixels(job.result(), reference);
        assertThat(job.result().rays().toString()).isEqualTo(reference.rays().toString());
    }

    /**
     * Every query of a render, put to the kd-tree and to the BVH: the same answer, or, where a ray
     * meets the edge two triangles share (pixel centres of a 24 x 18 image land exactly on the
     * room's edges), two equally close triangles, either of which is right (the oracle's rule);
     * kd-trees of two builders differ there too, and so may the pixel, when the two are of
     * different materials.
     */
    @Test void whereTheBvhAndTheKdTreeDisagreeTheHitsAreTies() throws Exception {
        Scene s = TestRenders.scene("cornell-box.json", 24, 18, 1);
        TriangleIntersector in = new TriangleIntersector(s.mesh());
        RayQuery kd = BuilderSpec.of("sah").build(s.mesh(), null).query(), bvh = BuilderSpec.of("bvh").build(s.mesh(), null).query();
        int[] asked = new int[1];
        RayQuery both = new RayQuery() {
            private final Hit other = new Hit(), probe = new Hit();

            @Override public boolean closestHit(Ray ray, double tMin, double tMax, Hit hit) {
                asked[0]++;
                boolean found = kd.closestHit(ray, tMin, tMax, hit);
                assertThat(bvh.closestHit(ray, tMin, tMax, other)).as("%s found", ray).isEqualTo(found);
                if (found && other.primitive != hit.primitive) {
                    assertThat(other.t).as("%s: a tie, kd %s, bvh %s", ray, hit, other).isCloseTo(hit.t, within(1e-12 * hit.t));
                    assertThat(in.intersect(hit.primitive, ray, tMin, tMax, probe.reset()) && probe.t == hit.t).isTrue();
                } else if (found) {
                    assertThat(other.t).as("%s: the same triangle at the same t", ray).isEqualTo(hit.t);
                }
                return found;
            }

            @Override public boolean anyHit(Ray ray, double tMin, double tMax) {
                asked[0]++;
                boolean found = kd.anyHit(ray, tMin, tMax);
                assertThat(bvh.anyHit(ray, tMin, tMax)).as("%s any hit", ray).isEqualTo(found);
                return found;
            }
        };
        Renderer.render(s, () -> both, Renderer.Options.defaults().withThreads(1));
        assertThat(asked[0]).isGreaterThan(24 * 18);
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
