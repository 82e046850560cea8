package org.kdtree.gui;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Files;
import java.nio.file.Path;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The 3-D view renders a bundled JSON scene with the ray tracer and builds an OBJ mesh's tree (headless). */
class View3DTest {
    private static String run(View3D v) throws Exception {
        SwingUtilities.invokeAndWait(v::build);
        long deadline = System.nanoTime() + 60_000_000_000L;
        boolean[] busy = {true};
        while (busy[0] && System.nanoTime() < deadline) {
            Thread.sleep(50);
            SwingUtilities.invokeAndWait(() -> busy[0] = v.busy());
        }
        assertThat(busy[0]).as("render finished in time").isFalse();
        String[] text = new String[1];
        SwingUtilities.invokeAndWait(() -> text[0] = v.statisticsText());
        return text[0];
    }

    @Test void rendersAJsonSceneProgressivelyAndReportsRays() throws Exception {
        View3D v = new View3D(new WorkbenchModel(), Path.of("scenes"));
        assertThat(View3D.sceneFiles(Path.of("scenes"))).contains("cornell-box.json", "clustered-spheres.obj");
        SwingUtilities.invokeAndWait(() -> v.choose("cornell-box.json", 48));
        String text = run(v);
        assertThat(text).contains("image: 48 x").contains("rays:").contains("camera").contains("build time").contains("nodes:");
        assertThat(v.image().getWidth()).isEqualTo(48);
        int lit = 0;
        for (int y = 0; y < v.image().getHeight(); y++)
            for (int x = 0; x < 48; x++) if ((v.image().getRGB(x, y) & 0xFFFFFF) != 0) lit++;
        assertThat(lit).as("the Cornell box is not black").isGreaterThan(48 * v.image().getHeight() / 4);
    }

    @Test void fromAnEmptyFolderTheBundledCornellBoxRenders(@TempDir Path empty) throws Exception {
        View3D v = new View3D(new WorkbenchModel(), empty.resolve("scenes"));
        SwingUtilities.invokeAndWait(() -> v.choose("cornell-box.json", 32));
        String text = run(v);
        assertThat(text).contains("image: 32 x").contains("rays:").contains("nodes:");
        int lit = 0;
        for (int y = 0; y < v.image().getHeight(); y++)
            for (int x = 0; x < 32; x++) if ((v.image().getRGB(x, y) & 0xFFFFFF) != 0) lit++;
        assertThat(lit).as("the bundled Cornell box is not black").isGreaterThan(32 * v.image().getHeight() / 4);
    }

    @Test void anOpenedObjMeshIsOfferedAndBuilt(@TempDir Path dir) throws Exception {
        Path mesh = Files.copy(Path.of("scenes/meshes/mtl-demo.obj"), dir.resolve("mine.obj"));
        View3D v = new View3D(new WorkbenchModel(), dir.resolve("no-such-folder"));
        SwingUtilities.invokeAndWait(() -> v.open(mesh));
        assertThat(run(v)).contains("statistics only").contains("nodes:");
        assertThatThrownBy(() -> v.open(dir.resolve("shapes.scene2d"))).hasMessageContaining("opens JSON scenes and OBJ meshes");
    }

    @Test void anObjMeshGetsItsTreeStatistics() throws Exception {
        View3D v = new View3D(new WorkbenchModel(), Path.of("scenes"));
        SwingUtilities.invokeAndWait(() -> v.choose("clustered-spheres.obj", 64));
        assertThat(run(v)).contains("statistics only").contains("nodes:").contains("expected cost:");
    }
}
