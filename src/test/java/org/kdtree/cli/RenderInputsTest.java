package org.kdtree.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Issue 34, item 6: render given a 2-D scene or a folder says what render takes, naming the scene
 * as the user gave it (never "malformed JSON", never a path inside the jar); issue 46, item 7: a
 * bare OBJ mesh renders, framed and lit.
 */
class RenderInputsTest {
    private static final String TAKES = ". render takes a JSON scene (camera, lights, materials, objects: docs/scene-format.md), "
            + "such as scenes:cornell-box, scenes:sphereflake, scenes:diffuse-only, scenes:shadows-only, scenes:obj-materials, "
            + "or an OBJ mesh, which it frames and lights";

    /** Issue 46, item 7: a bare mesh renders, framed and lit, and stderr says how it was set up. */
    @Test void aBareObjMeshRendersFramedAndLit(@TempDir Path dir) throws Exception {
        Path obj = Files.copy(Path.of("scenes/clustered-spheres.obj"), dir.resolve("teapot.obj"));
        Path png = dir.resolve("out.png");
        CliRun run = CliRun.of("render", obj.toString(), "-o", png.toString(), "-q");
        assertThat(run.code()).as(run.err()).isZero();
        assertThat(run.err()).contains("# " + obj + " is a bare mesh: framed by the benchmark's camera (512 x 512, 40 degrees)");
        BufferedImage image = ImageIO.read(png.toFile());
        assertThat(image.getWidth()).isEqualTo(512);
        int background = image.getRGB(0, 0), covered = 0, borderCovered = 0;
        java.util.Set<Integer> shades = new java.util.HashSet<>();
        for (int y = 0; y < image.getHeight(); y++)
            for (int x = 0; x < image.getWidth(); x++) {
                int rgb = image.getRGB(x, y);
                if (rgb == background) continue;
                covered++;
                shades.add(rgb & 0xff);
                if (x == 0 || y == 0 || x == image.getWidth() - 1 || y == image.getHeight() - 1) borderCovered++;
            }
        assertThat(covered).as("pixels showing the mesh").isGreaterThan(image.getWidth() * image.getHeight() / 20);
        assertThat(borderCovered).as("the mesh framed: nothing cut at the image's edges").isZero();
        assertThat(shades).as("lit: many shades of grey, not a flat silhouette").hasSizeGreaterThan(20);
    }

    @Test void aBundledMeshRendersAsAFileWould(@TempDir Path dir) {
        CliRun run = CliRun.of("render", "scenes:clustered-spheres", "-o", dir.resolve("out.png").toString(), "-q", "--width", "64",
                "--height", "64");
        assertThat(run.code()).as(run.err()).isZero();
        assertThat(run.err()).contains("# scenes:clustered-spheres is a bare mesh").doesNotContain("classes", "jar!");
        assertThat(dir.resolve("out.png")).exists();
    }

    @Test void aMeshWithoutTrianglesIsOneLine(@TempDir Path dir) throws Exception {
        Path obj = Files.writeString(dir.resolve("empty.obj"), "v 0 0 0\nv 1 0 0\n");
        CliRun run = CliRun.of("render", obj.toString(), "-o", dir.resolve("out.png").toString());
        assertThat(run.code()).isEqualTo(Failure.USAGE);
        assertThat(run.err().strip()).isEqualTo("error: " + obj + ": the mesh has no triangles to render");
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
