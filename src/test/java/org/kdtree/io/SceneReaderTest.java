package org.kdtree.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kdtree.render.EffectPlan;
import org.kdtree.scene.Light;
import org.kdtree.scene.Material;
import org.kdtree.scene.Scene;
import org.kdtree.shape.TriangleMesh;

/** JSON scenes, OBJ with usemtl and MTL libraries: content read, and errors that name file, line and field. */
class SceneReaderTest {
    @TempDir Path dir;

    private static final String CAMERA = "\"camera\": {\"eye\": [0, 0, 5], \"lookAt\": [0, 0, 0], \"fov\": 40, \"width\": 8, \"height\": 8}";

    private Path write(String name, String text) throws IOException {
        Path p = dir.resolve(name);
        Files.writeString(p, text);
        return p;
    }

    @Test void readsCameraLightsMaterialsAndBuiltInShapesIntoOneMesh() throws Exception {
        Path f = write("s.json", "{" + CAMERA + """
                ,
                 "samplesPerPixel": 4, "maxDepth": 3,
                 "materials": {"m": {"type": "mirror"}, "g": {"type": "glass", "ior": 1.33}},
                 "lights": [{"type": "area", "center": [0, 3, 0], "normal": [0, -1, 0], "size": 1, "samples": 9}],
                 "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "segments": 8, "material": "m"},
                             {"type": "box", "min": [-1, -1, -1], "max": [1, 1, 1], "material": "g",
                              "transform": [{"scale": 0.5}, {"rotate": {"axis": [0, 1, 0], "degrees": 45}}, {"translate": [2, 0, 0]}]},
                             {"type": "plane", "center": [0, -1, 0], "normal": [0, 1, 0], "size": [4, 2]}]}
                """);
        Scene s = SceneReader.read(f);
        assertThat(s.mesh().size()).isEqualTo(2 * 8 * 3 + 12 + 2);
        assertThat(s.samplesPerPixel()).isEqualTo(4);
        assertThat(s.maxDepth()).isEqualTo(3);
        assertThat(s.lights()).singleElement().isInstanceOf(Light.Area.class);
        assertThat(s.materials()).extracting(Material::name).containsExactly("m", "g", "default");
        assertThat(s.materials().get(1).ior()).isEqualTo(1.33);
        assertThat(s.geometryMayOcclude()).isTrue();
        // the box was scaled by 0.5 then moved to x = 2: its x range is 2 +- 0.5 * sqrt(2)
        double maxX = Double.NEGATIVE_INFINITY;
        for (int t = 48; t < 60; t++) for (int c = 0; c < 3; c++) maxX = Math.max(maxX, s.mesh().corner(t, c, 0));
        assertThat(maxX).isCloseTo(2 + 0.5 * Math.sqrt(2), org.assertj.core.data.Offset.offset(1e-12));
    }

    @Test void malformedJsonNamesFileAndLine() throws Exception {
        Path f = write("bad.json", "{\n  \"camera\": {\n    \"eye\": [0, 0 5]\n  }\n}\n");
        assertThatThrownBy(() -> SceneReader.read(f)).isInstanceOf(SceneFormatException.class)
                .hasMessageStartingWith(f + ":3: malformed JSON");
        Path empty = write("empty.json", "");
        assertThatThrownBy(() -> SceneReader.read(empty)).hasMessageStartingWith(empty + ":1: unexpected end of file");
        Path array = write("array.json", "[1, 2]");
        assertThatThrownBy(() -> SceneReader.read(array)).hasMessage(array + ":1: $: expected an object");
    }

    @Test void wrongFieldValueNamesFileLineAndField() throws Exception {
        Path f = write("bad.json", "{" + CAMERA + ",\n \"lights\": [\n  {\"type\": \"area\", \"center\": [0, 1, 0], \"normal\": [0, -1, 0],\n   \"size\": 1, \"samples\": -3}]}");
        assertThatThrownBy(() -> SceneReader.read(f)).isInstanceOf(SceneFormatException.class)
                .hasMessage(f + ":4: $.lights[0].samples: must be between 1 and 1024, got -3");
    }

    @Test void typosAndUnknownReferencesAreErrorsNotSilence() throws Exception {
        Path typo = write("t.json", "{" + CAMERA + ",\n \"objects\": [{\"type\": \"sphere\", \"center\": [0,0,0], \"radius\": 1, \"segmnts\": 8}]}");
        assertThatThrownBy(() -> SceneReader.read(typo)).hasMessageContaining(":2: $.objects[0].segmnts: unknown field 'segmnts'");
        Path ref = write("r.json", "{" + CAMERA + ",\n \"objects\": [{\"type\": \"box\", \"min\": [0,0,0], \"max\": [1,1,1],\n  \"material\": \"gold\"}]}");
        assertThatThrownBy(() -> SceneReader.read(ref)).hasMessageContaining(":3: $.objects[0].material: no material named 'gold'");
        Path missing = write("m.json", "{\"camera\": {\"eye\": [0, 0, 5], \"fov\": 40, \"width\": 8, \"height\": 8}}");
        assertThatThrownBy(() -> SceneReader.read(missing)).hasMessageContaining("$.camera: missing field 'lookAt'");
    }

    @Test void hugeGeneratedObjectsAreRefusedBeforeTheyExhaustMemory() throws Exception {
        Path f = write("big.json", "{" + CAMERA + ",\n \"objects\": [{\"type\": \"sphereflake\", \"center\": [0,0,0], \"radius\": 1, \"levels\": 6, \"segments\": 64}]}");
        assertThatThrownBy(() -> SceneReader.read(f)).hasMessageContaining(":2: $.objects[0]: would make")
                .hasMessageContaining("a scene holds at most 20000000");
    }

    @Test void objFacesTakeTheirUsemtlMaterialFromTheLibrary() throws Exception {
        write("m.mtl", "newmtl red\nKd 1 0 0\nillum 1\n\nnewmtl glass\nKs 1 1 1\nNi 1.5\nTf 0.9 0.9 0.9\nillum 7\n");
        write("a.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nusemtl glass\nf 1 3 4\nusemtl red\nf 4 3 2\n");
        Path f = write("s.json", "{" + CAMERA + ", \"materials\": {\"grey\": {\"type\": \"diffuse\"}},"
                + "\"objects\": [{\"type\": \"obj\", \"file\": \"a.obj\", \"material\": \"grey\"}]}");
        Scene s = SceneReader.read(f);
        assertThat(s.mesh().size()).isEqualTo(3);
        assertThat(s.materials()).extracting(Material::name).containsExactly("grey", "glass", "red");
        assertThat(s.geometry().materialOf(0)).isZero();   // before any usemtl: the object's material
        assertThat(s.geometry().materialOf(1)).isEqualTo(1);
        assertThat(s.geometry().materialOf(2)).isEqualTo(2);
        Material glass = s.materials().get(1);
        assertThat(glass.refracts()).isTrue();
        assertThat(glass.reflects()).isTrue();
        assertThat(glass.fresnel()).isTrue();
        assertThat(glass.ior()).isCloseTo(1.5, org.assertj.core.data.Offset.offset(1e-6));
    }

    @Test void objAndMtlErrorsNameTheirOwnFileAndLine() throws Exception {
        write("bad.mtl", "newmtl a\nKd 1 0 0\nNs lots\n");
        write("a.obj", "mtllib bad.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nusemtl a\nf 1 2 3\n");
        Path f = write("s.json", "{" + CAMERA + ", \"objects\": [{\"type\": \"obj\", \"file\": \"a.obj\"}]}");
        assertThatThrownBy(() -> SceneReader.read(f)).hasMessage(dir.resolve("bad.mtl") + ":3: Ns: 'lots' is not a non-negative number");

        write("good.mtl", "newmtl a\nKd 1 0 0\n");
        write("b.obj", "mtllib good.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nusemtl b\nf 1 2 3\n");
        Path g = write("t.json", "{" + CAMERA + ", \"objects\": [{\"type\": \"obj\", \"file\": \"b.obj\"}]}");
        assertThatThrownBy(() -> SceneReader.read(g)).hasMessageStartingWith(dir.resolve("b.obj") + ":5: usemtl b: no such material");

        Path none = write("n.json", "{" + CAMERA + ",\n \"objects\": [{\"type\": \"obj\", \"file\": \"nope.obj\"}]}");
        assertThatThrownBy(() -> SceneReader.read(none)).hasMessageStartingWith(none + ":2: $.objects[0].file: no such file");

        write("c.obj", "v 0 0 0\nv 1 0 0\nf 1 2 7\n");
        Path h = write("u.json", "{" + CAMERA + ", \"objects\": [{\"type\": \"obj\", \"file\": \"c.obj\"}]}");
        assertThatThrownBy(() -> SceneReader.read(h)).hasMessageStartingWith(dir.resolve("c.obj") + ":3: vertex index 7 out of range");
    }

    @Test void mtlIllumModelsMapOntoTheEffectPlan() throws Exception {
        StringBuilder mtl = new StringBuilder();
        for (int i = 0; i <= 10; i++) mtl.append("newmtl i").append(i).append("\nKd 0.5 0.5 0.5\nKs 0.5 0.5 0.5\nNi 1.5\nillum ").append(i).append('\n');
        Path lib = write("all.mtl", mtl.toString());
        var ms = MaterialReader.read(lib);
        String reflects = "", refracts = "", unlit = "";
        for (int i = 0; i <= 10; i++) {
            Material m = ms.get("i" + i);
            if (m.reflects()) reflects += i + " ";
            if (m.refracts()) refracts += i + " ";
            if (!m.lit()) unlit += i + " ";
        }
        assertThat(reflects).isEqualTo("3 4 5 6 7 ");
        assertThat(refracts).isEqualTo("4 6 7 9 ");
        assertThat(unlit).isEqualTo("0 ");
        assertThat(ms.get("i7").fresnel()).isTrue();
        assertThat(ms.get("i6").fresnel()).isFalse();
        assertThat(ms.get("i4").ior()).isEqualTo(1.0);   // "glass": transparency without bending
        assertThat(ms.get("i2").specular().x()).isEqualTo(0.5);
        assertThat(ms.get("i1").specular().isZero()).isTrue();
        assertThatThrownBy(() -> MaterialReader.read(write("x.mtl", "newmtl a\nillum 12\n"))).hasMessageContaining("x.mtl:2: illum must be");
        assertThatThrownBy(() -> MaterialReader.read(write("y.mtl", "newmtl a\nKd 1 1 1\nillum 2.0\n")))
                .hasMessageEndingWith("y.mtl:3: illum must be a whole number from 0 to 10 (digits only), got 2.0");
    }

    @Test void aSceneReadsAnObjFileAsTheCommandsDoTriangleForTriangle() throws Exception {
        TriangleMesh mesh = ObjMeshReader.read(Path.of("scenes/meshes/mtl-demo.obj"));
        TriangleMesh scene = SceneReader.read(Path.of("scenes/obj-materials.json")).mesh();
        assertThat(scene.indices()).isEqualTo(mesh.indices());
        assertThat(scene.vertices()).isEqualTo(mesh.vertices());
    }
}
