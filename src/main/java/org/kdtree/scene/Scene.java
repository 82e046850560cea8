package org.kdtree.scene;

import java.util.List;
import org.kdtree.limits.Limits;
import org.kdtree.shape.TriangleMesh;

/**
 * Everything a render needs: camera, lights, and all triangles in one {@link TriangleMesh} with
 * a material index per triangle (and vertex normals for smoothly shaded triangles).
 *
 * @param name               for reports (usually the file name)
 * @param camera             the pinhole camera, with the image size
 * @param lights             the lights (may be empty)
 * @param background         radiance of rays that leave the scene
 * @param ambient            constant ambient light, multiplied by each material's diffuse colour
 * @param geometry           triangles, materials and normals
 * @param materials          the materials that {@code geometry.materialOf} refers to
 * @param samplesPerPixel    camera rays per pixel (1: through the pixel centre; more: stratified jitter)
 * @param maxDepth           the longest chain of reflection/refraction rays after the camera ray
 * @param geometryMayOcclude false when the geometry cannot shadow itself (none, or one convex shape)
 * @param seed               base seed of the deterministic per-pixel sampling
 */
public record Scene(String name, Camera camera, List<Light> lights, Vec3 background, Vec3 ambient,
                    SceneGeometry geometry, List<Material> materials, int samplesPerPixel, int maxDepth,
                    boolean geometryMayOcclude, long seed) {

    /**
     * Checks the samples per pixel and the depth limit.
     *
     * @param name for reports (usually the file name)
     * @param camera the pinhole camera, with the image size
     * @param lights the lights (may be empty)
     * @param background radiance of rays that leave the scene
     * @param ambient constant ambient light, multiplied by each material's diffuse colour
     * @param geometry triangles, materials and normals
     * @param materials the materials that {@code geometry.materialOf} refers to
     * @param samplesPerPixel camera rays per pixel
     * @param maxDepth the longest chain of reflection/refraction rays after the camera ray
     * @param geometryMayOcclude false when the geometry cannot shadow itself
     * @param seed base seed of the deterministic per-pixel sampling
     */
    public Scene {
        Limits.SAMPLES_PER_PIXEL.check("samplesPerPixel", samplesPerPixel);
        Limits.RAY_DEPTH.check("maxDepth", maxDepth);
    }

    /** {@return all triangles of the scene} */
    public TriangleMesh mesh() { return geometry.mesh(); }

    /**
     * {@return this scene with the image size changed}
     *
     * @param width the image width in pixels
     * @param height the image height in pixels
     */
    public Scene withImageSize(int width, int height) {
        return new Scene(name, camera.withSize(width, height), lights, background, ambient, geometry, materials,
                samplesPerPixel, maxDepth, geometryMayOcclude, seed);
    }

    /**
     * {@return this scene with {@code spp} camera rays per pixel}
     *
     * @param spp samples per pixel
     */
    public Scene withSamplesPerPixel(int spp) {
        return new Scene(name, camera, lights, background, ambient, geometry, materials, spp, maxDepth,
                geometryMayOcclude, seed);
    }

    /**
     * {@return this scene with another depth limit}
     *
     * @param depth the longest chain of reflection/refraction rays after the camera ray
     */
    public Scene withMaxDepth(int depth) {
        return new Scene(name, camera, lights, background, ambient, geometry, materials, samplesPerPixel, depth,
                geometryMayOcclude, seed);
    }

    /**
     * {@return this scene with other materials}
     *
     * @param newMaterials the materials, indexed as the geometry's
     */
    public Scene withMaterials(List<Material> newMaterials) {
        return new Scene(name, camera, lights, background, ambient, geometry, List.copyOf(newMaterials),
                samplesPerPixel, maxDepth, geometryMayOcclude, seed);
    }

    /**
     * {@return this scene with other lights}
     *
     * @param newLights the lights
     */
    public Scene withLights(List<Light> newLights) {
        return new Scene(name, camera, List.copyOf(newLights), background, ambient, geometry, materials,
                samplesPerPixel, maxDepth, geometryMayOcclude, seed);
    }
}
