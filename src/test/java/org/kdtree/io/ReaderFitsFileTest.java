package org.kdtree.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kdtree.shape.TriangleMesh;

/**
 * Issue 34, item 5: the OBJ reader reads meshes only. A JSON scene, a 2-D scene or any file of
 * no triangles is refused in one line (naming the reader that fits a scene file), never read as
 * an empty mesh; every bundled scene opens through the reader of its kind.
 */
class ReaderFitsFileTest {
    @Test void theObjReaderRefusesOtherScenesNamingTheirReader() {
        Path json = Path.of("scenes/cornell-box.json"), scene2d = Path.of("scenes/talk-figures.scene2d");
        assertThatThrownBy(() -> ObjMeshReader.read(json)).isInstanceOf(SceneFormatException.class).hasMessage(json
                + ": a JSON render scene, not an OBJ mesh; read it with SceneReader.read (its triangles: PrimitivesReader.readMesh)");
        assertThatThrownBy(() -> ObjMeshReader.read(scene2d)).isInstanceOf(SceneFormatException.class).hasMessage(scene2d
                + ": a 2-D scene (.scene2d), not an OBJ mesh; read it with Scene2DReader.read (any scene's primitives: PrimitivesReader.read)");
        assertThatThrownBy(() -> SceneReader.read(Path.of("scenes/clustered-spheres.obj"))).isInstanceOf(SceneFormatException.class)
                .hasMessageContaining("an OBJ mesh, not a JSON render scene; read it with ObjMeshReader.read");
        assertThatThrownBy(() -> Scene2DReader.read(json)).isInstanceOf(SceneFormatException.class)
                .hasMessageContaining("a JSON render scene, not a 2-D scene (.scene2d)");
    }

    @Test void aFileOfNoTrianglesIsNoMesh(@TempDir Path dir) throws Exception {
        for (Path f : new Path[] {Path.of("README.md"), Files.writeString(dir.resolve("empty.obj"), ""),
                Files.writeString(dir.resolve("points.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\n")})
            assertThatThrownBy(() -> ObjMeshReader.read(f)).as(f.toString()).isInstanceOf(SceneFormatException.class)
                    .hasMessage(f + ": no triangles (no 'f' lines): not an OBJ mesh, or an empty one");
    }

    @Test void aCommentMayEndAFaceLine() throws Exception {
        TriangleMesh m = ObjMeshReader.read(new StringReader("v 0 0 0 # origin\nv 1 0 0\nv 0 1 0\nf 1 2 3 # the face\n"), "c.obj");
        assertThat(m.size()).isEqualTo(1);
        assertThat(m.corner(0, 1, 0)).isEqualTo(1.0);
    }

    @Test void everyBundledSceneOpensThroughTheReaderOfItsKind() throws Exception {
        for (String file : BundledScenes.FILES) {
            Path p = BundledScenes.resolve(BundledScenes.PREFIX + file);
            assertThat(PrimitivesReader.read(p).size()).as(file).isPositive();
            if (file.endsWith(".scene2d")) {
                assertThat(Scene2DReader.read(p).size()).as(file).isPositive();
                assertThatThrownBy(() -> PrimitivesReader.readMesh(p)).as(file).hasMessageEndingWith("a 2-D scene (.scene2d) has no "
                        + "triangles; give an .obj mesh or a .json scene");
            } else {
                assertThat(PrimitivesReader.readMesh(p).size()).as(file).isPositive();
            }
            if (file.endsWith(".json")) assertThat(SceneReader.read(p).mesh().size()).as(file).isPositive();
            if (file.endsWith(".obj")) assertThat(ObjMeshReader.read(p).size()).as(file).isPositive();
        }
    }
}
