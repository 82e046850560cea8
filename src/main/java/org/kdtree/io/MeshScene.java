package org.kdtree.io;

import java.io.IOException;
import java.io.StringReader;
import java.nio.file.Path;
import org.kdtree.scene.Camera;
import org.kdtree.scene.Scene;
import org.kdtree.scene.Vec3;

/**
 * A bare OBJ mesh made a scene, so that {@code render teapot.obj} draws something sensible: the
 * benchmark's set-P camera framing the mesh's box (docs/benchmark-spec.md: from direction
 * (1, 0.5, 2), 1.5 box diagonals from its centre, 40 degrees, up +y), one directional light from
 * above the camera's side, a little ambient light, and the mesh's own MTL materials where it
 * names them (grey diffuse elsewhere, as for any object of a JSON scene). A JSON scene is how a
 * user chooses instead (docs/scene-format.md).
 */
final class MeshScene {
    /** The image's width and height, in pixels. */
    static final int SIDE = 512;
    /** The vertical field of view, in degrees (the benchmark camera's). */
    static final double FOV = 40;
    /** What {@link #read} chose, in words. */
    static final String DESCRIPTION = "a bare mesh: framed by the benchmark's camera (" + SIDE + " x " + SIDE + ", 40 degrees), "
            + "lit by one directional light, grey where its MTL names no material; a JSON scene chooses these (docs/scene-format.md)";
    private static final Vec3 VIEW = new Vec3(1, 0.5, 2).normalized();

    private MeshScene() {
    }

    /**
     * {@return the mesh of {@code obj} framed as a scene}
     *
     * @param obj an OBJ file
     * @throws IOException if it cannot be read or is malformed, naming the file and line
     */
    static Scene read(Path obj) throws IOException {
        PrimitivesReader.requireExists(obj);
        String name = obj.getFileName().toString();
        String json = "{\"camera\": {\"eye\": [0, 0, 1], \"lookAt\": [0, 0, 0], \"fov\": " + FOV + ", \"width\": " + SIDE
                + ", \"height\": " + SIDE + "}, \"ambient\": [0.12, 0.12, 0.12],"
                + " \"lights\": [{\"type\": \"directional\", \"direction\": [-0.4, -2.0, -2.0], \"color\": [0.9, 0.9, 0.9]}],"
                + " \"objects\": [{\"type\": \"obj\", \"file\": " + new com.google.gson.JsonPrimitive(name) + "}]}";
        Scene s = SceneReader.read(new StringReader(json), obj.toString(), obj.toAbsolutePath().getParent());
        if (s.mesh().size() == 0) throw new SceneFormatException(obj.toString(), 0, "the mesh has no triangles to render");
        return new Scene(name, framing(s), s.lights(), s.background(), s.ambient(), s.geometry(), s.materials(),
                s.samplesPerPixel(), s.maxDepth(), s.geometryMayOcclude(), s.seed());
    }


    /** The benchmark's camera around the box of every vertex the scene holds. */
    private static Camera framing(Scene s) {
        double[] v = s.mesh().vertices(), min = {v[0], v[1], v[2]}, max = min.clone();
        for (int i = 0; i < v.length; i++) {
            min[i % 3] = Math.min(min[i % 3], v[i]);
            max[i % 3] = Math.max(max[i % 3], v[i]);
        }
        Vec3 low = new Vec3(min[0], min[1], min[2]), high = new Vec3(max[0], max[1], max[2]);
        Vec3 centre = low.plus(high).times(0.5);
        double diagonal = high.minus(low).length();
        Vec3 eye = centre.plus(VIEW.times(1.5 * (diagonal > 0 ? diagonal : 1)));   // a mesh at one point: seen from 1.5 away
        return new Camera(eye, centre, new Vec3(0, 1, 0), FOV, SIDE, SIDE);
    }
}
