package org.kdtree.render;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Locale;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.kdtree.scene.Scene;
import org.kdtree.spec.Builders;

/**
 * No NaN, infinite or negative pixel, even where shading is fragile: coarse smooth-shaded glass
 * and mirror spheres (interpolated normals far from the facets'), total internal reflection,
 * cameras inside glass, grazing views, lights on surfaces.
 */
class NoInvalidPixelsTest {
    @Test void randomCamerasAroundCoarseGlassAndMirrorsGiveOnlyValidPixels() throws Exception {
        SplittableRandom rnd = new SplittableRandom(7);
        for (int run = 0; run < 12; run++) {
            double ex = rnd.nextDouble(-3, 3), ey = rnd.nextDouble(0.01, 3), ez = rnd.nextDouble(-3, 3);
            if (run % 4 == 0) { ex = 0.1; ey = 1; ez = 0.05; }   // inside the glass sphere
            String json = String.format(Locale.ROOT, """
                    {"camera": {"eye": [%f, %f, %f], "lookAt": [0, 0.8, 0], "fov": %f, "width": 20, "height": 16},
                     "maxDepth": 8, "samplesPerPixel": 2, "ambient": 0.1,
                     "materials": {"glass": {"type": "glass", "ior": %f}, "mirror": {"type": "mirror", "reflectivity": 1},
                                   "floor": {"type": "phong", "color": 0.5, "shininess": 1000}},
                     "lights": [{"type": "point", "position": [0, 0, 0]},
                                {"type": "area", "center": [1, 3, 0], "normal": [0, -1, 0], "size": 1, "samples": 4, "intensity": 5},
                                {"type": "directional", "direction": [0, -1, 0.0001]}],
                     "objects": [{"type": "sphere", "center": [0, 1, 0], "radius": 0.8, "segments": 6, "rings": 3, "material": "glass"},
                                 {"type": "sphere", "center": [1.5, 0.5, 0.5], "radius": 0.5, "segments": 5, "material": "mirror"},
                                 {"type": "plane", "center": [0, 0, 0], "normal": [0, 1, 0], "size": 8, "material": "floor"}]}
                    """, ex, ey, ez, rnd.nextDouble(10, 170), rnd.nextDouble(1, 2.5));
            Scene s = TestRenders.json(json);
            RenderResult r = RenderJob.run(s, Builders.create("sah"), Renderer.Options.defaults()).result();
            assertThat(r.image().hasInvalidPixels()).as("run %d: %s", run, json).isFalse();
        }
    }
}
