package org.kdtree.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class RenderCommandTest {
    @TempDir Path dir;

    private static CliRun run(String... args) {
        return CliRun.of(args);
    }

    @Test void rendersTheCornellBoxToPngWithSummaryAndNoBarIntoALog() throws Exception {
        Path png = java.nio.file.Files.createDirectories(dir.resolve("out")).resolve("cornell.png");
        CliRun r = run("render", "scenes/cornell-box.json", "-o", png.toString(), "--builder", "sah", "--lambda", "0.8",
                "--threads", "2", "--spp", "1", "--width", "32", "--height", "24");
        assertThat(r.code()).as(r.err()).isZero();
        BufferedImage img = ImageIO.read(png.toFile());
        assertThat(img.getWidth()).isEqualTo(32);
        assertThat(img.getHeight()).isEqualTo(24);
        assertThat(r.out()).contains("effects: direct light", "reflection", "refraction", "soft shadows")
                .contains("build time: ", "render time: ", "rays/s", "camera", "shadow", "nodes: ", "wrote " + png)
                .contains("image: 32 x 24, 1 sample per pixel, 2 threads");
        assertThat(r.err()).as("no bar redrawn into output that is not a terminal").doesNotContain("\r").doesNotContain("tiles)");
    }

    /** The render names on stderr its structure, which tracer traced it through which loop, and the path. */
    @Test void theRenderNamesItsStructureTracerAndPath() throws Exception {
        CliRun kd = run("render", "scenes/cornell-box.json", "-o", dir.resolve("k.png").toString(), "--spp", "1", "--width", "16", "--height", "16");
        assertThat(kd.code()).as(kd.err()).isZero();
        assertThat(kd.err()).contains("# structure: kd-tree (sah)")
                .contains("# tracer: the recursive tracer, one pixel at a time, each ray through the single-ray loop "
                        + "(the structure's packet loop is slower in renders than its single rays)")
                .contains("# path: ");
        CliRun bvh = run("render", "scenes/cornell-box.json", "-o", dir.resolve("b.png").toString(), "--spp", "1", "--width", "16", "--height", "16",
                "-b", "bvh");
        assertThat(bvh.code()).as(bvh.err()).isZero();
        assertThat(bvh.err()).contains("# structure: bvh (bvh)")
                .contains("# tracer: the recursive tracer, one pixel at a time, each ray through the single-ray loop "
                        + "(the structure's packet loop is slower in renders than its single rays)").contains("# path: ");
    }

    /** {@code --blocks} traces through the block tracer and the packet loop, which neither structure repays, and writes the same image. */
    @Test void blocksAreTracedWhenAskedForAndGiveTheSameImage() throws Exception {
        for (String builder : new String[] {"sah", "bvh"}) {
            Path alone = dir.resolve(builder + "-alone.png"), blocks = dir.resolve(builder + "-blocks.png");
            String[] common = {"scenes/cornell-box.json", "--spp", "2", "--width", "20", "--height", "12", "-b", builder};
            CliRun a = run(concat(new String[] {"render", "-o", alone.toString()}, common));
            CliRun b = run(concat(new String[] {"render", "--blocks", "-o", blocks.toString()}, common));
            assertThat(a.code()).as(a.err()).isZero();
            assertThat(b.code()).as(b.err()).isZero();
            assertThat(b.err()).contains("# tracer: blocks of 8 x 8 pixels, breadth first, their rays in packets through the packet loop "
                    + "(asked for; slower in renders than single rays)");
            assertThat(Files.readAllBytes(blocks)).as(builder).isEqualTo(Files.readAllBytes(alone));
        }
    }

    private static String[] concat(String[] a, String[] b) {
        String[] all = java.util.Arrays.copyOf(a, a.length + b.length);
        System.arraycopy(b, 0, all, a.length, b.length);
        return all;
    }

    @Test void rayDepthZeroTurnsReflectionAndRefractionOff() throws Exception {
        CliRun r = run("render", "scenes/cornell-box.json", "-o", dir.resolve("c.png").toString(), "--ray-depth", "0",
                "--spp", "1", "--width", "16", "--height", "16", "-q");
        assertThat(r.code()).as(r.err()).isZero();
        assertThat(r.out()).contains("max depth: 0").doesNotContain("reflection,").doesNotContain("refraction,")
                .containsPattern("reflection +0\\R").containsPattern("refraction +0\\R");
        assertThat(r.err()).isEmpty();
    }

    @Test void aMalformedSceneGivesOneClearLineAndNoStackTrace() throws Exception {
        Path bad = dir.resolve("bad.json");
        Files.writeString(bad, "{\"camera\": {\"eye\": [0, 0, 5], \"lookAt\": [0, 0, 0], \"fov\": 400,\n \"width\": 8, \"height\": 8}}");
        CliRun r = run("render", bad.toString(), "-o", dir.resolve("x.png").toString());
        assertThat(r.code()).isEqualTo(2);
        assertThat(r.err().strip()).isEqualTo("error: " + bad + ":1: $.camera.fov: field of view must be more than 0 and less than 180 degrees (both ends excluded), got 400.0");
        Files.writeString(bad, "{\"camera\": {\"eye\": [0, 0, 5], \"lookAt\": [0, 0, 0], \"fov\": 0,\n \"width\": 8, \"height\": 8}}");
        r = run("render", bad.toString(), "-o", dir.resolve("x.png").toString());
        assertThat(r.err().strip()).as("issue 46, item 9: 0 itself is refused, so the ends are said to be excluded")
                .endsWith("field of view must be more than 0 and less than 180 degrees (both ends excluded), got 0.0");
        r = run("render", dir.resolve("missing.json").toString());
        assertThat(r.code()).isEqualTo(2);
        assertThat(r.err()).contains("missing.json: no such file").doesNotContain("Exception");
        r = run("render", "scenes/diffuse-only.json", "--ray-depth", "-1");
        assertThat(r.err()).contains("--ray-depth must be between 0 and 64, got -1");
        r = run("render", "scenes/diffuse-only.json", "--threads", "0");
        assertThat(r.err()).contains("--threads must be between 1 and 256, got 0");
    }
}
