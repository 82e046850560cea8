package org.kdtree.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Issue 34, item 6: render given an OBJ mesh or a 2-D scene says what render takes, naming the
 * scene as the user gave it (never "malformed JSON", never a path inside the jar).
 */
class RenderInputsTest {
    private static final String TAKES = ". render takes a JSON scene (camera, lights, materials, objects: docs/scene-format.md), "
            + "such as scenes:cornell-box, scenes:sphereflake, scenes:diffuse-only, scenes:shadows-only, scenes:obj-materials";

    @Test void anObjMeshIsToldHowToRenderIt(@TempDir Path dir) throws Exception {
        Path obj = Files.copy(Path.of("scenes/clustered-spheres.obj"), dir.resolve("bunny.obj"));
        Path png = dir.resolve("out.png");
        CliRun run = CliRun.of("render", obj.toString(), "-o", png.toString());
        assertThat(run.code()).isEqualTo(Failure.USAGE);
        assertThat(run.err().strip()).isEqualTo("error: SCENE " + obj + ": is an OBJ mesh, with no camera or lights; put it in a JSON "
                + "scene as an object {\"type\": \"obj\", \"file\": \"bunny.obj\"} (docs/scene-format.md), or trace it with stats or raycast"
                + TAKES);
        assertThat(png).doesNotExist();
    }

    @Test void aBundledMeshIsNamedAsTheUserGaveIt(@TempDir Path dir) {
        CliRun run = CliRun.of("render", "scenes:clustered-spheres", "-o", dir.resolve("out.png").toString());
        assertThat(run.code()).isEqualTo(Failure.USAGE);
        assertThat(run.err()).startsWith("error: SCENE scenes:clustered-spheres: is an OBJ mesh").doesNotContain("malformed", "classes", "jar!");
    }

    @Test void aTwoDimensionalSceneIsSentToTheWorkbench(@TempDir Path dir) throws Exception {
        CliRun run = CliRun.of("render", "scenes:talk-figures", "-o", dir.resolve("out.png").toString());
        assertThat(run.code()).isEqualTo(Failure.USAGE);
        assertThat(run.err().strip()).isEqualTo("error: SCENE scenes:talk-figures: is a 2-D scene; open it in the workbench (gui) or "
                + "give it to stats" + TAKES);
        CliRun folder = CliRun.of("render", dir.toString(), "-o", dir.resolve("out.png").toString());
        assertThat(folder.err().strip()).isEqualTo("error: SCENE " + dir + ": is a folder, not a file" + TAKES);
    }
}
