package org.kdtree.io;

import java.io.IOException;
import java.io.StringReader;
import java.nio.file.Path;
import org.kdtree.generate.MeshGrid;
import org.kdtree.geom.Box;
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
    static final String DESCRIPTION = "a bare mesh: framed by the benchmark's camera (" + SIDE + " x " + SIDE + ", " + (int) FOV + " degrees), "
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
        Box b = MeshGrid.vertexBounds(s.mesh());   // the benchmark's box: every vertex, used or not
        Vec3 low = new Vec3(b.min(0), b.min(1), b.min(2)), high = new Vec3(b.max(0), b.max(1), b.max(2));
        Vec3 centre = low.plus(high).times(0.5);
        double diagonal = high.minus(low).length();
        Vec3 eye = centre.plus(VIEW.times(1.5 * (diagonal > 0 ? diagonal : 1)));   // a mesh at one point: seen from 1.5 away
        return new Camera(eye, centre, new Vec3(0, 1, 0), FOV, SIDE, SIDE);
    }
}
