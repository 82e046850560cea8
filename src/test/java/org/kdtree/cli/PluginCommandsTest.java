package org.kdtree.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kdtree.spec.Builders;
import org.kdtree.testing.PluginJars;
import org.kdtree.testing.PluginMidpointBuilder;

/**
 * A builder from a jar that only declares it in META-INF/services (a student's) joins stats,
 * raycast and render, with no change to this project's code: the architecture issue's last item.
 */
class PluginCommandsTest {
    @TempDir Path dir;

    @AfterEach void forgetThePlugIn() {
        Builders.remove(new PluginMidpointBuilder().name());
    }

    @Test void statsRaycastAndRenderBuildWithAPluggedInBuilder() throws Exception {
        Path jar = PluginJars.listing(dir, "student.jar", PluginMidpointBuilder.class.getName());

        CliRun stats = CliRun.of("--plugin", jar.toString(), "stats", "scenes/clustered-spheres.obj", "-b", "plugin-midpoint");
        assertThat(stats.code()).as(stats.err()).isZero();
        assertThat(stats.out()).contains("builder: plugin-midpoint").contains("nodes: ");

        Path rays = dir.resolve("rays.txt"), hits = dir.resolve("hits.txt");
        Files.writeString(rays, "0 1 -20 0 0 1\n0 100 0 0 1 0\n");
        CliRun raycast = CliRun.of("--plugin", jar.toString(), "raycast", "scenes/clustered-spheres.obj", "-b", "plugin-midpoint",
                "--rays", rays.toString(), "--hits", hits.toString());
        assertThat(raycast.code()).as(raycast.err()).isZero();
        assertThat(Files.readAllLines(hits)).hasSize(2).element(1).isEqualTo("miss");

        Path png = dir.resolve("box.png");
        CliRun render = CliRun.of("--plugin", jar.toString(), "render", "scenes:cornell-box", "-b", "plugin-midpoint",
                "--width", "24", "--spp", "1", "-o", png.toString());
        assertThat(render.code()).as(render.err()).isZero();
        assertThat(Files.size(png)).isPositive();
    }
}
