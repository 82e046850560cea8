package org.kdtree.render;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.kdtree.accel.BruteForce;
import org.kdtree.accel.Hit;
import org.kdtree.accel.TriangleIntersector;
import org.kdtree.geom.Ray;
import org.kdtree.scene.Camera;
import org.kdtree.scene.Material;
import org.kdtree.scene.Scene;
import org.kdtree.scene.Vec3;

/** The effect plan decides which rays are cast: counted by kind. */
class RayCountTest {

    @Test void diffuseOnlySceneCastsNoReflectionOrRefractionRays() throws Exception {
        RenderResult r = TestRenders.bruteForce(TestRenders.scene("diffuse-only.json", 32, 24, 1), 2);
        assertThat(r.rays().get(RayKind.CAMERA)).isEqualTo(32 * 24);
        assertThat(r.rays().get(RayKind.REFLECTION)).isZero();
        assertThat(r.rays().get(RayKind.REFRACTION)).isZero();
        assertThat(r.rays().get(RayKind.SHADOW)).as("its lights cast no shadows").isZero();
        assertThat(r.plan().effects()).containsExactly(Effect.DIRECT_LIGHT);
    }

    @Test void shadowsOnlySceneCastsShadowRaysButNoReflectionOrRefraction() throws Exception {
        RenderResult r = TestRenders.bruteForce(TestRenders.scene("shadows-only.json", 32, 24, 1), 2);
        assertThat(r.rays().get(RayKind.SHADOW)).isPositive();
        assertThat(r.rays().get(RayKind.REFLECTION)).isZero();
        assertThat(r.rays().get(RayKind.REFRACTION)).isZero();
        assertThat(r.plan().effects()).containsExactlyInAnyOrder(Effect.DIRECT_LIGHT, Effect.SHADOWS, Effect.SOFT_SHADOWS);
    }

    @Test void sceneWithoutLightsCastsNoShadowRays() throws Exception {
        Scene s = TestRenders.scene("shadows-only.json", 24, 16, 1).withLights(List.of());
        RenderResult r = TestRenders.bruteForce(s, 1);
        assertThat(r.rays().get(RayKind.SHADOW)).isZero();
        assertThat(r.rays().get(RayKind.CAMERA)).isEqualTo(24 * 16);
    }

    @Test void oneConvexObjectCannotShadowItself() throws Exception {
        Scene s = TestRenders.json("""
                {"camera": {"eye": [0, 0, 5], "lookAt": [0, 0, 0], "fov": 30, "width": 16, "height": 16},
                 "lights": [{"type": "point", "position": [2, 3, 4], "intensity": 20}],
                 "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "segments": 16}]}""");
        RenderResult r = TestRenders.bruteForce(s, 1);
        assertThat(r.rays().get(RayKind.SHADOW)).isZero();
        assertThat(r.plan().effects()).containsExactly(Effect.DIRECT_LIGHT);
    }

    @Test void oneMirrorMakesReflectionRaysAppearOnlyFromPixelsThatSeeIt() throws Exception {
        Scene diffuse = TestRenders.scene("shadows-only.json", 40, 30, 1);
        int orange = indexOf(diffuse, "orange");
        List<Material> ms = new ArrayList<>(diffuse.materials());
        ms.set(orange, Material.mirror("orange", new Vec3(0.1, 0.05, 0), new Vec3(0.8, 0.8, 0.8)));
        Scene mirror = diffuse.withMaterials(ms);

        assertThat(TestRenders.bruteForce(diffuse, 2).rays().get(RayKind.REFLECTION)).isZero();
        RenderResult r = TestRenders.bruteForce(mirror, 2);
        assertThat(r.plan().effects()).contains(Effect.REFLECTION);

        BruteForce oracle = new BruteForce(new TriangleIntersector(mirror.mesh()));
        Camera cam = mirror.camera();
        Ray ray = new Ray(3);
        Hit hit = new Hit();
        int seeing = 0;
        for (int y = 0; y < 30; y++) {
            for (int x = 0; x < 40; x++) {
                double[] d = new double[3];
                cam.direction(x + 0.5, y + 0.5, d);
                ray.set(cam.eye().x(), cam.eye().y(), cam.eye().z(), d[0], d[1], d[2]);
                boolean seesMirror = oracle.closestHit(ray, 0, Double.POSITIVE_INFINITY, hit)
                        && mirror.geometry().materialOf(hit.primitive) == orange;
                if (seesMirror) seeing++;
                assertThat(r.pixelRays(RayKind.REFLECTION, x, y)).as("pixel %d,%d", x, y)
                        .isEqualTo(seesMirror ? 1 : 0);
            }
        }
        assertThat(seeing).isGreaterThan(10);
        assertThat(r.rays().get(RayKind.REFLECTION)).isEqualTo(seeing);
        assertThat(r.rays().get(RayKind.REFRACTION)).isZero();
    }

    @Test void cornellBoxSimulatesEveryEffect() throws Exception {
        RenderResult r = TestRenders.bruteForce(TestRenders.scene("cornell-box.json", 24, 24, 1), 2);
        for (RayKind k : RayKind.values()) assertThat(r.rays().get(k)).as(k.label()).isPositive();
        assertThat(r.plan().effects()).contains(Effect.SOFT_SHADOWS, Effect.REFLECTION, Effect.REFRACTION,
                Effect.FRESNEL, Effect.SPECULAR_HIGHLIGHTS, Effect.EMISSION);
        assertThat(r.image().hasInvalidPixels()).isFalse();
    }

    private static int indexOf(Scene s, String name) {
        for (int i = 0; i < s.materials().size(); i++) if (s.materials().get(i).name().equals(name)) return i;
        throw new AssertionError("no material " + name);
    }
}
