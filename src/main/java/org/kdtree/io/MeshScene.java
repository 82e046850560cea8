package org.kdtree.io;

import java.io.IOException;
import java.io.StringReader;
import java.nio.file.Path;
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
public final class MeshScene {
    /** The image's width and height, in pixels. */
    public static final int SIDE = 512;
    /** The vertical field of view, in degrees (the benchmark camera's). */
    public static final double FOV = 40;
    private static final Vec3 VIEW = new Vec3(1, 0.5, 2).normalized();

    private MeshScene() {
    }

    /**
     * {@return the mesh of {@code obj} framed as a scene}
     *
     * @param obj an OBJ file
     * @throws IOException if it cannot be read or is malformed, naming the file and line
     */
    public static Scene read(Path obj) throws IOException {
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

    /** {@return what {@link #read} chose, in one line, for the user to see} */
    public static String describe() {
        return "a bare mesh: framed by the benchmark's camera (" + SIDE + " x " + SIDE + ", " + (int) FOV
                + " degrees), lit by one directional light, grey where its MTL names no material; a JSON scene chooses these "
                + "(docs/scene-format.md)";
    }

    /** The benchmark's camera around the box of every vertex the scene holds. */
    private static Camera framing(Scene s) {
        double[] v = s.mesh().vertices();
        Box b = new Box(3);
        for (int i = 0; i < v.length; i += 3) b.grow(v, i);
        Vec3 centre = new Vec3((b.min(0) + b.max(0)) / 2, (b.min(1) + b.max(1)) / 2, (b.min(2) + b.max(2)) / 2);
        double diagonal = Math.sqrt(b.extent(0) * b.extent(0) + b.extent(1) * b.extent(1) + b.extent(2) * b.extent(2));
        Vec3 eye = centre.plus(VIEW.times(1.5 * Math.max(diagonal, 1e-9)));
        return new Camera(eye, centre, new Vec3(0, 1, 0), FOV, SIDE, SIDE);
    }
}
