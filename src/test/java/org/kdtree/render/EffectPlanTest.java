package org.kdtree.render;

import org.kdtree.scene.Scene;
import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

/** The plan's decisions, checked by exact ray counts on scenes where every camera ray hits a lit floor. */
class EffectPlanTest {
    static final int W = 12, H = 10;

    /** Looking straight down at a large floor; a box far outside the view makes occlusion possible. */
    static Scene floor(String light, String floorMaterial, int maxDepth) throws Exception {
        return TestRenders.json("""
                {"camera": {"eye": [0, 5, 0], "lookAt": [0, 0, 0], "up": [0, 0, -1], "fov": 30, "width": %d, "height": %d},
                 "maxDepth": %d,
                 "materials": {"floor": %s},
                 "lights": [%s],
                 "objects": [{"type": "plane", "center": [0, 0, 0], "normal": [0, 1, 0], "size": 100, "material": "floor"},
                             {"type": "box", "min": [40, 0, 40], "max": [41, 1, 41], "material": "floor"}]}
                """.formatted(W, H, maxDepth, floorMaterial, light));
    }

    static final String DIFFUSE = "{\"type\": \"diffuse\"}";
    static final String POINT = "{\"type\": \"point\", \"position\": [0, 3, 0], \"intensity\": 5}";
    static final String AREA9 = "{\"type\": \"area\", \"center\": [0, 3, 0], \"normal\": [0, -1, 0], \"size\": 1, \"samples\": 9}";

    @Test void pointLightCastsOneShadowRayPerShadedPoint() throws Exception {
        RenderResult r = TestRenders.bruteForce(floor(POINT, DIFFUSE, 5), 1);
        assertThat(r.rays().get(RayKind.SHADOW)).isEqualTo(W * H);
        assertThat(r.plan().effects()).containsExactlyInAnyOrder(Effect.DIRECT_LIGHT, Effect.SHADOWS);
    }

    @Test void areaLightSamplesOnlyForAreaLights() throws Exception {
        RenderResult r = TestRenders.bruteForce(floor(AREA9 + ", " + POINT, DIFFUSE, 5), 1);
        assertThat(r.rays().get(RayKind.SHADOW)).isEqualTo(10L * W * H);
        assertThat(r.plan().lightSamples(0)).isEqualTo(9);
        assertThat(r.plan().lightSamples(1)).isEqualTo(1);
        assertThat(r.plan().effects()).contains(Effect.SOFT_SHADOWS, Effect.SHADOWS);
    }

    @Test void lightsThatCastNoShadowsGetNoShadowRays() throws Exception {
        RenderResult r = TestRenders.bruteForce(floor(AREA9.replace("}", ", \"shadows\": false}") + ", " + POINT, DIFFUSE, 5), 1);
        assertThat(r.rays().get(RayKind.SHADOW)).isEqualTo(W * H);
    }

    @Test void mirrorReflectsOnlyWhileDepthAllows() throws Exception {
        String mirror = "{\"type\": \"mirror\", \"reflectivity\": 0.5}";
        RenderResult deep = TestRenders.bruteForce(floor(POINT, mirror, 5), 1);
        assertThat(deep.rays().get(RayKind.REFLECTION)).isEqualTo(W * H);   // up into the empty sky: one each
        RenderResult flat = TestRenders.bruteForce(floor(POINT, mirror, 0), 1);
        assertThat(flat.rays().get(RayKind.REFLECTION)).isZero();
        assertThat(flat.plan().effects()).doesNotContain(Effect.REFLECTION);
    }

    @Test void negligiblePathWeightStopsRecursion() throws Exception {
        String faint = "{\"type\": \"mirror\", \"reflectivity\": 0.0005}";
        RenderResult r = TestRenders.bruteForce(floor(POINT, faint, 5), 1);
        assertThat(r.plan().effects()).contains(Effect.REFLECTION);
        assertThat(r.rays().get(RayKind.REFLECTION)).isZero();
    }

    @Test void unlitMaterialsNeedNoShadowRays() throws Exception {
        String unlit = "{\"type\": \"diffuse\", \"color\": 0, \"emission\": [1, 0, 0]}";
        RenderResult r = TestRenders.bruteForce(floor(POINT, unlit, 5), 1);
        assertThat(r.rays().get(RayKind.SHADOW)).isZero();
        assertThat(r.plan().effects()).containsExactly(Effect.EMISSION);
        assertThat(r.image().get(0, 0, 0)).isEqualTo(1f);
    }

    @Test void glassRefractsAndReflectsWithFresnel() throws Exception {
        String glass = "{\"type\": \"glass\", \"ior\": 1.5}";
        RenderResult r = TestRenders.bruteForce(floor(POINT, glass, 1), 1);
        assertThat(r.rays().get(RayKind.REFRACTION)).isEqualTo(W * H);
        assertThat(r.rays().get(RayKind.REFLECTION)).isEqualTo(W * H);   // F is about 0.04 near normal incidence
        assertThat(r.plan().effects()).contains(Effect.REFRACTION, Effect.REFLECTION, Effect.FRESNEL);
        assertThat(r.image().hasInvalidPixels()).isFalse();
    }
}
