package org.kdtree.io;

import java.io.IOException;
import java.io.Reader;
import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.kdtree.geom.Tolerance;
import org.kdtree.limits.Limits;
import org.kdtree.scene.Camera;
import org.kdtree.scene.GeometryBuilder;
import org.kdtree.scene.Light;
import org.kdtree.scene.Material;
import org.kdtree.scene.Scene;
import org.kdtree.scene.Vec3;

/**
 * Reads a JSON scene (docs/scene-format.md) into a {@link Scene}: all triangles of all objects
 * in one mesh with a material per triangle. Every error names the file, the line and the field.
 */
final class SceneReader {
    /** Generated triangles allowed in one scene (about 1.5 GB with the tree): a typo must not exhaust memory. */
    static final long MAX_TRIANGLES = 20_000_000;
    private final String file;
    private final Path dir;
    private final List<Material> materials = new ArrayList<>();
    private final Map<String, Integer> materialIndex = new LinkedHashMap<>();
    private final GeometryBuilder geometry = new GeometryBuilder();

    private SceneReader(String file, Path dir) {
        this.file = file;
        this.dir = dir;
    }

    /**
     * {@return the scene of a scene file}; OBJ files it names are resolved against its folder.
     *
     * @param path the scene file
     * @throws IOException if a file cannot be read or is malformed
     */
    public static Scene read(Path path) throws IOException {
        FileKind.JSON.require(path);
        try (Reader r = new StringReader(TextLines.readAll(path))) {
            Path dir = path.toAbsolutePath().getParent();
            return new SceneReader(path.toString(), dir).parse(JsonNode.read(r, path.toString()),
                    path.getFileName().toString());
        }
    }

    /**
     * {@return the scene of scene JSON text}
     *
     * @param reader the JSON text
     * @param name used in error messages
     * @param dir the folder OBJ files are resolved against
     * @throws IOException if a file cannot be read or is malformed
     */
    public static Scene read(Reader reader, String name, Path dir) throws IOException {
        return new SceneReader(name, dir).parse(JsonNode.read(reader, name), name);
    }

    private Scene parse(JsonNode root, String name) throws IOException {
        root.allowOnly("name", "camera", "background", "ambient", "samplesPerPixel", "maxDepth", "seed",
                "materials", "lights", "objects");
        Camera camera = camera(root.get("camera"));
        Vec3 background = root.has("background") ? vec(root.get("background")) : Vec3.ZERO;
        Vec3 ambient = root.has("ambient") ? vec(root.get("ambient")) : Vec3.ZERO;
        int spp = root.has("samplesPerPixel") ? root.get("samplesPerPixel").integer(Limits.SAMPLES_PER_PIXEL) : 1;
        int maxDepth = root.has("maxDepth") ? root.get("maxDepth").integer(Limits.RAY_DEPTH) : 5;
        long seed = root.has("seed") ? root.get("seed").integer(0, Integer.MAX_VALUE) : 1;
        if (root.has("materials")) {
            JsonNode ms = root.get("materials");
            for (String m : ms.fieldNames()) addMaterial(m, material(m, ms.get(m)));
        }
        List<Light> lights = new ArrayList<>();
        if (root.has("lights")) for (JsonNode l : root.get("lights").array()) lights.add(light(l));
        List<JsonNode> objects = root.has("objects") ? root.get("objects").array() : List.of();
        boolean mayOcclude = objects.size() > 1;
        for (JsonNode o : objects) mayOcclude |= !object(o);
        String title = root.has("name") ? root.get("name").string() : name;
        return new Scene(title, camera, List.copyOf(lights), background, ambient, geometry.finish(),
                List.copyOf(materials), spp, maxDepth, mayOcclude, seed);
    }

    private Camera camera(JsonNode c) throws SceneFormatException {
        c.allowOnly("eye", "lookAt", "up", "fov", "width", "height");
        Vec3 eye = vec(c.get("eye")), at = vec(c.get("lookAt"));
        Vec3 up = c.has("up") ? vec(c.get("up")) : new Vec3(0, 1, 0);
        if (at.minus(eye).length() == 0) throw c.get("lookAt").error("must differ from eye");
        if (at.minus(eye).normalized().cross(up.normalized()).length() < Tolerance.PARALLEL_SINE) throw c.get("up").error("must not be parallel to the view direction");
        JsonNode fov = c.get("fov");
        double f = fov.number();
        if (f <= 0 || f >= 180) throw fov.error("field of view must be more than 0 and less than 180 degrees (both ends excluded), got " + f);
        return new Camera(eye, at, up, f, c.get("width").integer(Limits.IMAGE_SIDE),
                c.get("height").integer(Limits.IMAGE_SIDE));
    }

    private Material material(String name, JsonNode m) throws SceneFormatException {
        m.allowOnly("type", "color", "specular", "shininess", "reflectivity", "ior", "tint", "emission");
        String type = m.get("type").string();
        Vec3 color = m.has("color") ? vec(m.get("color")) : new Vec3(0.8, 0.8, 0.8);
        Material result = switch (type) {
            case "diffuse" -> Material.diffuse(name, color);
            case "phong" -> Material.phong(name, color, m.has("specular") ? vec(m.get("specular")) : Vec3.ONE,
                    m.has("shininess") ? m.get("shininess").number(0) : 32);
            case "mirror" -> Material.mirror(name, m.has("color") ? color : Vec3.ZERO,
                    m.has("reflectivity") ? vec(m.get("reflectivity")) : Vec3.ONE.times(0.9));
            case "glass" -> Material.glass(name, m.has("tint") ? vec(m.get("tint")) : Vec3.ONE,
                    m.has("ior") ? m.get("ior").number(1) : 1.5);
            default -> throw m.get("type").error("unknown material type '" + type + "' (diffuse, phong, mirror, glass)");
        };
        return m.has("emission") ? result.withEmission(vec(m.get("emission"))) : result;
    }

    private Light light(JsonNode l) throws SceneFormatException {
        String type = l.get("type").string();
        Vec3 color = (l.has("color") ? vec(l.get("color")) : Vec3.ONE)
                .times(l.has("intensity") ? l.get("intensity").number(0) : 1);
        boolean shadows = !l.has("shadows") || l.get("shadows").bool();
        switch (type) {
            case "point" -> {
                l.allowOnly("type", "position", "color", "intensity", "shadows");
                return new Light.Point(vec(l.get("position")), color, shadows);
            }
            case "directional" -> {
                l.allowOnly("type", "direction", "color", "intensity", "shadows");
                return new Light.Directional(unit(l.get("direction")), color, shadows);
            }
            case "area" -> {
                l.allowOnly("type", "center", "normal", "size", "samples", "color", "intensity", "shadows");
                double size = l.get("size").number();
                if (size <= 0) throw l.get("size").error("must be positive");
                int samples = l.has("samples") ? l.get("samples").integer(Limits.LIGHT_SAMPLES) : 16;
                return new Light.Area(vec(l.get("center")), unit(l.get("normal")), size, samples, color, shadows);
            }
            default -> throw l.get("type").error("unknown light type '" + type + "' (point, directional, area)");
        }
    }

    /** Adds one object's triangles; returns whether it is a convex shape (cannot shadow itself). */
    private boolean object(JsonNode o) throws IOException {
        String type = o.get("type").string();
        geometry.resetTransform();
        if (o.has("transform")) transform(o.get("transform"));
        switch (type) {
            case "sphere" -> {
                o.allowOnly("type", "center", "radius", "segments", "rings", "material", "transform");
                int seg = o.has("segments") ? o.get("segments").integer(Limits.SPHERE_SEGMENTS) : 48;
                int rings = o.has("rings") ? o.get("rings").integer(Limits.SPHERE_RINGS) : Math.max(2, seg / 2);
                limit(o, 2L * seg * (rings - 1));
                geometry.sphere(vec(o.get("center")), positive(o.get("radius")), seg, rings, materialOf(o));
                return true;
            }
            case "box" -> {
                o.allowOnly("type", "min", "max", "material", "transform");
                Vec3 min = vec(o.get("min")), max = vec(o.get("max"));
                if (min.x() > max.x() || min.y() > max.y() || min.z() > max.z()) throw o.get("max").error("must not be below min");
                geometry.box(min, max, materialOf(o));
                return true;
            }
            case "plane" -> {
                o.allowOnly("type", "center", "normal", "size", "material", "transform");
                double[] size = o.get("size").isNumber() ? new double[] {o.get("size").number(), o.get("size").number()}
                        : pair(o.get("size"));
                geometry.plane(vec(o.get("center")), unit(o.get("normal")), size[0], size[1], materialOf(o));
                return true;
            }
            case "sphereflake" -> {
                o.allowOnly("type", "center", "radius", "levels", "segments", "rings", "material", "transform");
                int seg = o.has("segments") ? o.get("segments").integer(Limits.SPHERE_SEGMENTS) : 12;
                int rings = o.has("rings") ? o.get("rings").integer(Limits.SPHERE_RINGS) : Math.max(2, seg / 2);
                int levels = o.get("levels").integer(Limits.FLAKE_LEVELS);
                limit(o, ((long) Math.pow(9, levels + 1) - 1) / 8 * 2L * seg * (rings - 1));
                geometry.sphereflake(vec(o.get("center")), positive(o.get("radius")), levels, seg, rings,
                        materialOf(o));
                return false;
            }
            case "obj" -> {
                o.allowOnly("type", "file", "material", "transform");
                obj(o);
                return false;
            }
            default -> throw o.get("type").error("unknown object type '" + type + "' (sphere, box, plane, sphereflake, obj)");
        }
    }

    /** Refuses an object that would not fit in memory, before generating it. */
    private void limit(JsonNode o, long triangles) throws SceneFormatException {
        if (geometry.triangleCount() + triangles > MAX_TRIANGLES)
            throw o.error("would make " + triangles + " triangles; a scene holds at most " + MAX_TRIANGLES);
    }

    /** Streams the OBJ's vertices and faces straight into the scene's arrays, then resolves its materials. */
    private void obj(JsonNode o) throws IOException {
        Path path = dir.resolve(o.get("file").string());
        if (!Files.isRegularFile(path)) throw o.get("file").error("no such file: " + path);
        int base = geometry.vertexCount(), first = geometry.triangleCount();
        ObjMeshReader.Materials used = ObjMeshReader.read(path, new ObjMeshReader.Sink() {
            @Override public void vertex(double x, double y, double z) { geometry.vertex(x, y, z); }
            @Override public void triangle(int a, int b, int c, int material) {
                geometry.triangle(base + a, base + b, base + c, material, false);
            }
        });
        int[] global = materials(path, used);
        int fallback = -1;
        for (int t = first; t < geometry.triangleCount(); t++) {
            int m = geometry.materialOf(t);
            if (m < 0 && fallback < 0) fallback = materialOf(o);
            geometry.material(t, m < 0 ? fallback : global[m]);
        }
    }

    /** The scene's index of each material the OBJ file names, from its MTL libraries. */
    private int[] materials(Path path, ObjMeshReader.Materials used) throws IOException {
        Map<String, Material> library = new LinkedHashMap<>();
        for (Path lib : used.libraries()) {
            if (!Files.isRegularFile(lib))
                throw new SceneFormatException(path.toString(), 0, "mtllib " + lib.getFileName() + ": no such file (" + lib + ")");
            library.putAll(MaterialReader.read(lib));
        }
        int[] global = new int[used.names().size()];
        for (int i = 0; i < global.length; i++) {
            String m = used.names().get(i);
            Material mat = library.get(m);
            if (mat == null)
                throw new SceneFormatException(path.toString(), used.firstUse().get(i),
                        "usemtl " + m + ": no such material in " + (used.libraries().isEmpty() ? "any mtllib (none given)" : used.libraries()));
            global[i] = addMaterial(path.getFileName() + ":" + m, mat);
        }
        return global;
    }

    private int addMaterial(String name, Material m) {
        Integer old = materialIndex.get(name);
        if (old != null) return old;
        materials.add(m);
        materialIndex.put(name, materials.size() - 1);
        return materials.size() - 1;
    }

    /** The object's material by name; a grey diffuse "default" when none is given. */
    private int materialOf(JsonNode o) throws SceneFormatException {
        if (!o.has("material")) return addMaterial("default", Material.diffuse("default", new Vec3(0.7, 0.7, 0.7)));
        String name = o.get("material").string();
        Integer i = materialIndex.get(name);
        if (i == null) throw o.get("material").error("no material named '" + name + "' (defined: " + materialIndex.keySet() + ")");
        return i;
    }

    /** A list of steps applied in order: {"translate": v}, {"scale": s or v}, {"rotate": {"axis": v, "degrees": a}}. */
    private void transform(JsonNode t) throws SceneFormatException {
        for (JsonNode step : t.array()) {
            step.allowOnly("translate", "scale", "rotate");
            if (step.fieldNames().size() != 1) throw step.error("each transform step has exactly one of translate, scale, rotate");
            if (step.has("translate")) {
                geometry.translate(vec(step.get("translate")));
            } else if (step.has("scale")) {
                Vec3 v = vec(step.get("scale"));
                if (v.x() == 0 || v.y() == 0 || v.z() == 0) throw step.get("scale").error("a scale of 0 flattens the object");
                geometry.scale(v);
            } else {
                JsonNode r = step.get("rotate").allowOnly("axis", "degrees");
                Vec3 axis = unit(r.get("axis"));
                geometry.rotate(r.get("degrees").number(), axis);
            }
        }
    }

    private static Vec3 vec(JsonNode n) throws SceneFormatException {
        double[] t = n.triple();
        return new Vec3(t[0], t[1], t[2]);
    }

    private static Vec3 unit(JsonNode n) throws SceneFormatException {
        Vec3 v = vec(n);
        if (v.length() == 0) throw n.error("direction must not be zero");
        return v.normalized();
    }

    private static double positive(JsonNode n) throws SceneFormatException {
        double d = n.number();
        if (d <= 0) throw n.error("must be positive, got " + d);
        return d;
    }

    private static double[] pair(JsonNode n) throws SceneFormatException {
        List<JsonNode> a = n.array();
        if (a.size() != 2) throw n.error("expected [width, height]");
        return new double[] {positive(a.get(0)), positive(a.get(1))};
    }
}
