package org.kdtree.render;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import org.junit.jupiter.api.Test;
import org.kdtree.accel.BruteForce;
import org.kdtree.accel.Hit;
import org.kdtree.accel.TriangleIntersector;
import org.kdtree.geom.Ray;
import org.kdtree.scene.Scene;

/**
 * The shader's records of one hit, checked against Whitted's model worked out by hand: a point on
 * a floor under a point light, a directional light from above, one from below and a four-sample
 * area light; what a diffuse, a mirror and a glass floor send on; the depth limit; a miss.
 */
class ShaderTest {
    /** Lights in this order, so slots: point 0, from above 1, from below 2, area 3 to 6. */
    private static final String LIGHTS = """
            {"type": "point", "position": [0, 3, 0], "intensity": 5},
            {"type": "directional", "direction": [0, -1, 0], "color": 0.5},
            {"type": "directional", "direction": [0, 1, 0]},
            {"type": "area", "center": [0, 3, 0], "normal": [0, -1, 0], "size": 1, "samples": 4}""";

    private static Scene scene(String floor) throws Exception {
        return TestRenders.json("""
                {"camera": {"eye": [0, 5, 0], "lookAt": [0, 0, 0], "up": [0, 0, -1], "fov": 30, "width": 8, "height": 8},
                 "maxDepth": 2, "ambient": 0.1, "background": 0.2,
                 "materials": {"floor": %s},
                 "lights": [%s],
                 "objects": [{"type": "plane", "center": [0, 0, 0], "normal": [0, 1, 0], "size": 100, "material": "floor"},
                             {"type": "box", "min": [40, 0, 40], "max": [41, 1, 41], "material": "floor"}]}
                """.formatted(floor, LIGHTS));
    }

    /** The shader of the last {@link #shadeDown}. */
    private Shader shader;

    /** Shades the hit of the ray from (0.5, 2, 0.25) straight down, at {@code point} of its ray tree. */
    private Shading shadeDown(Scene s, long point) {
        Ray ray = new Ray(3).set(0.5, 2, 0.25, 0, -1, 0);
        Hit hit = new Hit();
        boolean found = new BruteForce(new TriangleIntersector(s.mesh())).closestHit(ray, 0, Double.POSITIVE_INFINITY, hit);
        assertThat(found).isTrue();
        PixelSampler sampler = new PixelSampler(s);
        sampler.startSample(0, 0, 0);
        Shading out = new Shading(new LightSamples());
        shader = new Shader(s, new EffectPlan(s));
        shader.shade(true, hit, new double[] {0, -1, 0}, point, 1, sampler, out);
        return out;
    }

    /** {@return channel {@code c} of the light sample {@code i} of the last {@link #shadeDown} brings to the eye} */
    private double light(LightSamples l, int i, int c) {
        double[] rgb = new double[3];
        shader.reflected(l, i, rgb);
        return rgb[c];
    }

    @Test void aDiffusePointGetsItsLightSamplesWithTheirShadowRaysAndSendsNothingOn() throws Exception {
        Shading out = shadeDown(scene("{\"type\": \"diffuse\", \"color\": 0.5}"), 1);
        assertThat(out.base).containsExactly(0.1 * 0.5, 0.1 * 0.5, 0.1 * 0.5);          // ambient times diffuse, no emission
        assertThat(out.lit).isTrue();
        LightSamples l = out.lights;
        assertThat(l.size()).as("point, the light from above, four area samples; none from below").isEqualTo(6);
        assertThat(new int[] {l.slot(0), l.slot(1), l.slot(2), l.slot(3), l.slot(4), l.slot(5)}).containsExactly(0, 1, 3, 4, 5, 6);
        for (int i = 0; i < 6; i++) assertThat(l.shadowed(i)).isTrue();

        // The point light: Lambert's cosine over the squared distance, times its power; the ray stops just short of it.
        double dx = -0.5, dy = 3, dz = -0.25, d2 = dx * dx + dy * dy + dz * dz, cos = dy / Math.sqrt(d2);
        for (int c = 0; c < 3; c++) assertThat(light(l, 0, c)).isCloseTo(0.5 * cos * 5 / d2, within(1e-15));
        Ray shadow = l.shadowRay(0, new Ray(3));
        assertThat(shadow.origin(1)).as("just above the floor").isPositive().isLessThan(1e-6);
        assertThat(shadow.origin(0) + shadow.direction(0)).isCloseTo(0, within(1e-12));
        assertThat(shadow.origin(1) + shadow.direction(1)).isCloseTo(3, within(1e-12));
        assertThat(l.end(0)).isEqualTo(Shader.SHADOW_END).isLessThan(1);

        // The directional light from above: no falloff, its ray without end straight up.
        assertThat(l.toward(1, 0) == 0 && l.toward(1, 1) == 1 && l.toward(1, 2) == 0).as("its direction, straight up").isTrue();
        assertThat(l.falloff(1)).isEqualTo(1);
        for (int c = 0; c < 3; c++) assertThat(light(l, 1, c)).isEqualTo(0.5 * 0.5);
        shadow = l.shadowRay(1, shadow);
        assertThat(shadow.direction(0) == 0 && shadow.direction(1) == 1 && shadow.direction(2) == 0).as("straight up").isTrue();
        assertThat(l.end(1)).isEqualTo(Double.POSITIVE_INFINITY);

        // The area light's samples: a quarter of its light each, falling off, toward points of its square.
        for (int i = 2; i < 6; i++) {
            shadow = l.shadowRay(i, shadow);
            double qx = shadow.origin(0) + shadow.direction(0), qy = shadow.origin(1) + shadow.direction(1), qz = shadow.origin(2) + shadow.direction(2);
            assertThat(qy).isCloseTo(3, within(1e-12));
            assertThat(Math.abs(qx)).isLessThanOrEqualTo(0.5 + 1e-12);
            assertThat(Math.abs(qz)).isLessThanOrEqualTo(0.5 + 1e-12);
            assertThat(light(l, i, 0)).isPositive().isLessThan(0.25 * 0.5 / (3 * 3 - 1e-9));
        }
        assertThat(out.reflection.followed).isFalse();
        assertThat(out.refraction.followed).isFalse();
    }

    @Test void aMirrorSendsItsReflectionWithItsWeight() throws Exception {
        Shading out = shadeDown(scene("{\"type\": \"mirror\", \"reflectivity\": 0.9}"), 1);
        SecondaryRay r = out.reflection;
        assertThat(r.followed).isTrue();
        assertThat(r.direction[0] == 0 && r.direction[1] == 1 && r.direction[2] == 0).as("straight up").isTrue();
        assertThat(r.weight).containsExactly(0.9, 0.9, 0.9);
        assertThat(r.pathWeight).isEqualTo(0.9);
        assertThat(r.origin[1]).isPositive().isLessThan(1e-6);
        assertThat(r.point(1)).isEqualTo(2);
        assertThat(out.refraction.followed).isFalse();
        assertThat(shadeDown(scene("{\"type\": \"mirror\", \"reflectivity\": 0.9}"), 4).reflection.followed)
                .as("at the depth limit (point 4 is depth 2) nothing is sent on").isFalse();
    }

    @Test void glassSplitsTheWeightByFresnelAndRefractsStraightThroughAtNormalIncidence() throws Exception {
        Shading out = shadeDown(scene("{\"type\": \"glass\", \"ior\": 1.5}"), 1);
        double f = Math.pow((1.5 - 1) / (1.5 + 1), 2);                                  // 0.04 at normal incidence
        assertThat(out.reflection.followed).isTrue();
        assertThat(out.refraction.followed).isTrue();
        assertThat(out.refraction.point(1)).isEqualTo(3);
        assertThat(out.refraction.direction[1]).isCloseTo(-1, within(1e-15));
        assertThat(out.refraction.origin[1]).as("just below the surface").isNegative().isGreaterThan(-1e-6);
        for (int c = 0; c < 3; c++) {
            assertThat(out.reflection.weight[c]).isCloseTo(f, within(1e-12));
            assertThat(out.refraction.weight[c]).isCloseTo(1 - f, within(1e-12));
        }
    }

    @Test void aMissGivesTheBackgroundAndNothingElse() throws Exception {
        Scene s = scene("{\"type\": \"diffuse\"}");
        Shading out = new Shading(new LightSamples());
        out.lights.add(0, new double[] {0, 1, 0}, new double[] {1, 1, 1}, 1);                                                     // what the last hit left
        out.reflection.followed = true;
        PixelSampler sampler = new PixelSampler(s);
        sampler.startSample(0, 0, 0);
        new Shader(s, new EffectPlan(s)).shade(false, new Hit(), new double[] {0, 1, 0}, 1, 1, sampler, out);
        assertThat(out.base).containsExactly(0.2, 0.2, 0.2);
        assertThat(out.lit).isFalse();
        assertThat(out.lights.size()).isZero();
        assertThat(out.reflection.followed).isFalse();
        assertThat(out.refraction.followed).isFalse();
    }
}
