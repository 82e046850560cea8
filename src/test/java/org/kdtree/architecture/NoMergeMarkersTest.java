package org.kdtree.architecture;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/** No file of the project keeps a merge's conflict markers (one landed in docs/architecture.md once). */
class NoMergeMarkersTest {
    @Test void noSourceOrDocumentHoldsConflictMarkers() throws IOException {
        List<String> found = new ArrayList<>();
        for (Path root : List.of(Path.of("src"), Path.of("docs"), Path.of("scenes"), Path.of("README.md"), Path.of("pom.xml"))) {
            try (Stream<Path> files = Files.walk(root)) {
                for (Path f : files.filter(p -> p.toString().matches(".*\\.(java|md|xml|json|scene2d|txt|dot|sh)$")).toList()) {
                    List<String> lines = Files.readAllLines(f);
                    for (int i = 0; i < lines.size(); i++)
                        if (lines.get(i).matches("^(<{7}|>{7}) .*|^={7}$")) found.add(f + ":" + (i + 1));
                }
            }
        }
        assertThat(found).as("conflict markers").isEmpty();
    }
}
