package org.kdtree.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kdtree.shape.TriangleMesh;

class ObjMeshReaderTest {
    private static TriangleMesh read(String text) throws Exception {
        return ObjMeshReader.read(new StringReader(text), "test.obj");
    }

    @Test void readsEveryFaceFormAndFanTriangulatesPolygons() throws Exception {
        TriangleMesh m = read("""
                # a quad and a triangle
                v 0 0 0
                v 1 0 0
                v 1 1 0
                v 0 1 0
                vt 0 0
                vn 0 0 1
                f 1/1/1 2/1/1 3/1/1 4/1/1
                f -4//1 -3 -1/1
                o ignored
                """);
        assertThat(m.size()).isEqualTo(3);
        assertThat(m.indices()).containsExactly(0, 1, 2, 0, 2, 3, 0, 1, 3);
        assertThat(m.vertexCount()).isEqualTo(4);
    }

    @Test void errorsNameTheFileAndLine() {
        assertThatThrownBy(() -> read("v 0 0 0\nv 1 0 zero\n"))
                .isInstanceOf(SceneFormatException.class).hasMessage("test.obj:2: 'zero' is not a number");
        assertThatThrownBy(() -> read("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n"))
                .hasMessageStartingWith("test.obj:4: vertex index 4 out of range");
        assertThatThrownBy(() -> read("v 0 0 0\nf 1 1\n")).hasMessageContaining("test.obj:2: a face needs at least 3");
        assertThatThrownBy(() -> read("v 0 0\n")).hasMessageContaining("test.obj:1: a vertex needs x y z");
        assertThatThrownBy(() -> read("v 0 0 NaN\n")).hasMessageContaining("test.obj:1: coordinate NaN is not finite");
        assertThatThrownBy(() -> read("v 0 0 0\nf 0 1 1\n")).hasMessageContaining("vertex index 0");
    }

    @Test void theSceneReadsTheSameTrianglesAsTheCommandsWithAMaterialPerFace(@TempDir Path dir) throws Exception {
        Path obj = dir.resolve("m.obj");
        Files.writeString(obj, "mtllib a.mtl b.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\n"
                + "usemtl red\nf 1 2 3 4\nusemtl blue\nf -1 -2 -3\nusemtl red\nf 4 1 2\n");
        List<Integer> streamed = new ArrayList<>(), materials = new ArrayList<>();
        List<Double> coordinates = new ArrayList<>();
        ObjMeshReader.Materials used = ObjMeshReader.read(obj, new ObjMeshReader.Sink() {
            @Override public void vertex(double x, double y, double z) { coordinates.addAll(List.of(x, y, z)); }
            @Override public void triangle(int a, int b, int c, int material) {
                streamed.addAll(List.of(a, b, c));
                materials.add(material);
            }
        });
        TriangleMesh mesh = ObjMeshReader.read(obj);
        assertThat(streamed).containsExactlyElementsOf(Arrays.stream(mesh.indices()).boxed().toList());
        assertThat(coordinates).containsExactlyElementsOf(Arrays.stream(mesh.vertices()).boxed().toList());
        assertThat(materials).containsExactly(-1, 0, 0, 1, 0);
        assertThat(used.names()).containsExactly("red", "blue");
        assertThat(used.firstUse()).containsExactly(7, 9);
        assertThat(used.libraries()).containsExactly(dir.toAbsolutePath().resolve("a.mtl"), dir.toAbsolutePath().resolve("b.mtl"));
    }

    @Test void aMissingFileIsAClearError() {
        assertThatThrownBy(() -> ObjMeshReader.read(java.nio.file.Path.of("no/such/mesh.obj")))
                .isInstanceOf(SceneFormatException.class).hasMessage("no/such/mesh.obj: no such file");
    }
}
