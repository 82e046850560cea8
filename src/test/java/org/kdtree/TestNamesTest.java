package org.kdtree;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * Surefire runs only classes named {@code *Test}, {@code *Tests}, {@code Test*} or
 * {@code *TestCase}: a concrete class of tests or properties named otherwise would silently
 * never run (TraversalProperties did, until this check).
 */
class TestNamesTest {
    @Test void everyClassWithTestsHasANameSurefireRuns() throws IOException {
        List<String> unrun;
        try (Stream<Path> files = Files.walk(Path.of("src/test/java"))) {
            unrun = files.filter(f -> f.toString().endsWith(".java")).filter(TestNamesTest::holdsTests)
                    .map(f -> f.getFileName().toString().replace(".java", ""))
                    .filter(n -> !(n.endsWith("Test") || n.endsWith("Tests") || n.startsWith("Test") || n.endsWith("TestCase")))
                    .toList();
        }
        assertThat(unrun).as("classes with tests that surefire would never run").isEmpty();
    }

    private static boolean holdsTests(Path f) {
        try {
            String s = Files.readString(f);
            boolean tests = s.contains("@Test") || s.contains("@Property") || s.contains("@ParameterizedTest");
            return tests && !s.contains("abstract class");
        } catch (IOException e) {
            throw new IllegalStateException(f + ": " + e.getMessage(), e);
        }
    }
}
