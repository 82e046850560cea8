package org.kdtree.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.StringWriter;
import org.junit.jupiter.api.Test;
import org.kdtree.shape.Shapes2D;
import org.kdtree.generate.Shapes;

class Scene2DFormatTest {
    @Test void writeThenReadGivesTheSameShapes() throws Exception {
        Shapes2D scene = Shapes.mixed(40, 8);
        StringWriter out = new StringWriter();
        Scene2DFormat.write(scene, out);
        assertThat(Scene2DFormat.parse(out.toString(), "x").shapes()).isEqualTo(scene.shapes());
    }

    @Test void theBundledTalkSceneMatchesTheTestScene() throws Exception {
        Shapes2D fromFile = Scene2DFormat.read(java.nio.file.Path.of("scenes/talk-figures.scene2d"));
        assertThat(fromFile.shapes()).isEqualTo(BundledScenes.read2D("talk-figures.scene2d").shapes());
    }

    @Test void errorsNameTheFileAndLine() {
        assertThatThrownBy(() -> Scene2DFormat.parse("point 1 2\n# ok\ncircle 1 2 3\n", "s.scene2d"))
                .hasMessage("s.scene2d:3: unknown shape 'circle' (expected point, segment, rect or triangle)");
        assertThatThrownBy(() -> Scene2DFormat.parse("segment 1 2 3\n", "s.scene2d"))
                .hasMessage("s.scene2d:1: segment needs 4 numbers, got 3");
        assertThatThrownBy(() -> Scene2DFormat.parse("rect 1 2 x 4\n", "s.scene2d"))
                .hasMessage("s.scene2d:1: 'x' is not a number");
        assertThatThrownBy(() -> Scene2DFormat.parse("point Infinity 2\n", "s.scene2d"))
                .hasMessage("s.scene2d:1: coordinate Infinity is not finite");
    }
}
