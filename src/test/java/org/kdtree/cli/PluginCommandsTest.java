package org.kdtree.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kdtree.spec.Builders;
import org.kdtree.testing.PluginJars;
import org.kdtree.testing.PluginLeafyBuilder;
import org.kdtree.testing.PluginMidpointBuilder;

/**
 * A builder from a jar that only declares it in META-INF/services (a student's) joins stats,
 * raycast and render, with no change to this project's code: the architecture issue's last item.
 */
class PluginCommandsTest {
    @TempDir Path dir;

    @AfterEach void forgetThePlugIns() {
        Builders.remove(new PluginMidpointBuilder().name());
        Builders.remove(new PluginLeafyBuilder().name());
    }

    /** A plug-in declares a setting of its own: the command line offers it, checks its range and gives it to the builder. */
    @Test void aPluginsOwnSettingIsAnOptionThatReachesItsBuilder() throws Exception {
        Path jar = PluginJars.listing(dir, "leafy.jar", PluginLeafyBuilder.class.getName());

        CliRun three = CliRun.of("--plugin", jar.toString(), "stats", "scenes:cornell-box", "-b", "plugin-leafy", "--leaf-limit", "3");
        assertThat(three.code()).as(three.err()).isZero();
        assertThat(three.out()).contains("leafLimit=3");
        CliRun fifty = CliRun.of("--plugin", jar.toString(), "stats", "scenes:cornell-box", "-b", "plugin-leafy", "--leaf-limit", "50");
        assertThat(fifty.code()).as(fifty.err()).isZero();
        assertThat(nodes(three.out())).as("a smaller leaf limit splits more").isGreaterThan(nodes(fifty.out()));

        CliRun zero = CliRun.of("--plugin", jar.toString(), "stats", "scenes:cornell-box", "-b", "plugin-leafy", "--leaf-limit", "0");
        assertThat(zero.code()).isEqualTo(2);
        assertThat(zero.err().strip()).isEqualTo("error: --leaf-limit must be between 1 and 1000, got 0");

        CliRun sah = CliRun.of("--plugin", jar.toString(), "stats", "scenes:cornell-box", "-b", "sah", "--leaf-limit", "3");
        assertThat(sah.code()).isEqualTo(2);
        assertThat(sah.err()).contains("--leaf-limit applies to the plugin-leafy builder only, not to sah");

        CliRun help = CliRun.of("--plugin", jar.toString(), "stats", "--help");
        assertThat(help.out().replaceAll("\\s+", " ")).contains("--leaf-limit=N").contains("leaf limit: the largest node the plug-in makes a leaf of");
    }

    private static int nodes(String statsOut) {
        return Integer.parseInt(statsOut.lines().filter(l -> l.startsWith("nodes: ")).findFirst().orElseThrow().substring(7).strip());
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
