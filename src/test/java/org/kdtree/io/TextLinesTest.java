package org.kdtree.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kdtree.shape.TriangleMesh;

/** Every reader decodes through TextLines: a byte-order mark is skipped, a byte that is not UTF-8 names its file and line. */
class TextLinesTest {
    @TempDir Path dir;

    @Test void anObjThatStartsWithAByteOrderMarkKeepsItsFirstVertex() throws Exception {
        Path obj = dir.resolve("bom.obj");
        Files.writeString(obj, "\uFEFFv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", StandardCharsets.UTF_8);
        TriangleMesh mesh = ObjMeshReader.read(obj);
        assertThat(mesh.size()).isEqualTo(1);
        assertThat(mesh.vertexCount()).isEqualTo(3);
    }

    @Test void aLatin1ByteIsAOneLineErrorWithFileAndLine() throws Exception {
        Path obj = dir.resolve("cafe.obj");
        byte[] text = "v 0 0 0\nv 1 0 0\n# caf\u00e9\nv 0 1 0\nf 1 2 3\n".getBytes(StandardCharsets.ISO_8859_1);
        Files.write(obj, text);
        assertThatThrownBy(() -> ObjMeshReader.read(obj)).isInstanceOf(SceneFormatException.class)
                .hasMessage(obj + ":3: not UTF-8 text (column 6 holds a byte such as a Latin-1 accent); save the file as UTF-8");
        Path scene2d = dir.resolve("cafe.scene2d");
        Files.write(scene2d, "# caf\u00e9\nrect 0 0 1 1\n".getBytes(StandardCharsets.ISO_8859_1));
        assertThatThrownBy(() -> Scene2DReader.read(scene2d)).hasMessageStartingWith(scene2d + ":1: not UTF-8 text");
    }

    @Test void aByteOrderMarkIsSkippedInEveryFormat() throws Exception {
        Path scene2d = dir.resolve("bom.scene2d");
        Files.writeString(scene2d, "\uFEFFrect 0 0 1 1\n", StandardCharsets.UTF_8);
        assertThat(Scene2DReader.read(scene2d).size()).isEqualTo(1);
        Path json = dir.resolve("bom.json");
        Files.writeString(json, "\uFEFF" + Files.readString(Path.of("scenes/cornell-box.json")), StandardCharsets.UTF_8);
        assertThat(SceneReader.read(json)).isNotNull();
    }
}
