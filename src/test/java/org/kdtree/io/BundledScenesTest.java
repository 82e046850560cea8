package org.kdtree.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/** The bundled scenes are found by name from the class path, whatever the working directory. */
class BundledScenesTest {
    @Test void everySceneOfTheFolderIsBundledAndReadable() throws Exception {
        try (Stream<Path> files = Files.list(Path.of("scenes"))) {
            assertThat(BundledScenes.FILES).containsExactlyInAnyOrderElementsOf(
                    files.filter(Files::isRegularFile).map(p -> p.getFileName().toString()).toList());
        }
        for (String f : BundledScenes.FILES)
            if (!f.equals("sphereflake.json")) assertThat(PrimitivesReader.read(BundledScenes.path(f)).size()).as(f).isPositive();
    }

    @Test void aNameResolvesToTheBundledSceneUnlessSuchAFileExists() {
        Path cornell = BundledScenes.resolve("scenes:cornell-box");
        assertThat(cornell.getFileName().toString()).isEqualTo("cornell-box.json");
        assertThat(cornell.toUri()).isNotEqualTo(Path.of("scenes/cornell-box.json").toAbsolutePath().toUri());
        assertThat(BundledScenes.resolve("talk-figures").getFileName().toString()).isEqualTo("talk-figures.scene2d");
        assertThat(BundledScenes.resolve("pom.xml")).isEqualTo(Path.of("pom.xml"));
        assertThat(BundledScenes.resolve("no-such-file.obj")).isEqualTo(Path.of("no-such-file.obj"));
        assertThatThrownBy(() -> BundledScenes.resolve("scenes:nope"))
                .hasMessage("scenes:nope: no bundled scene of that name (bundled: talk-figures, uniform-200, clustered-200,"
                        + " long-thin, overlapping-60, cornell-box, sphereflake, diffuse-only, shadows-only, obj-materials, clustered-spheres)");
    }

    @Test void aJsonSceneNamingAnObjBesideItLoads() throws Exception {
        assertThat(PrimitivesReader.read(BundledScenes.path("obj-materials.json")).size()).isPositive();
    }
}
