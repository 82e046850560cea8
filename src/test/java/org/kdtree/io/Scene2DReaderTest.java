package org.kdtree.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.StringReader;
import java.io.StringWriter;
import org.junit.jupiter.api.Test;
import org.kdtree.shape.Scene2D;
import org.kdtree.testing.TestScenes;

/** The .scene2d format: what Scene2DWriter writes, Scene2DReader reads back; errors name the file and the line. */
class Scene2DReaderTest {
    @Test void writeThenReadGivesTheSameShapes() throws Exception {
        Scene2D scene = TestScenes.random2D(40, 8);
        StringWriter out = new StringWriter();
        Scene2DWriter.write(scene, out);
        assertThat(Scene2DReader.read(new StringReader(out.toString()), "x").shapes()).isEqualTo(scene.shapes());
    }

    @Test void theBundledTalkSceneMatchesTheTestScene() throws Exception {
        Scene2D fromFile = Scene2DReader.read(java.nio.file.Path.of("scenes/talk-figures.scene2d"));
        assertThat(fromFile.shapes()).isEqualTo(TestScenes.talkFigures().shapes());
    }

    @Test void errorsNameTheFileAndLine() {
        assertThatThrownBy(() -> Scene2DReader.read(new StringReader("point 1 2\n# ok\ncircle 1 2 3\n"), "s.scene2d"))
                .hasMessage("s.scene2d:3: unknown shape 'circle' (expected point, segment, rect or triangle)");
        assertThatThrownBy(() -> Scene2DReader.read(new StringReader("segment 1 2 3\n"), "s.scene2d"))
                .hasMessage("s.scene2d:1: segment needs 4 numbers, got 3");
        assertThatThrownBy(() -> Scene2DReader.read(new StringReader("rect 1 2 x 4\n"), "s.scene2d"))
                .hasMessage("s.scene2d:1: 'x' is not a number");
        assertThatThrownBy(() -> Scene2DReader.read(new StringReader("point Infinity 2\n"), "s.scene2d"))
                .hasMessage("s.scene2d:1: coordinate Infinity is not finite");
    }
}
