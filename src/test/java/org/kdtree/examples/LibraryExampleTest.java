package org.kdtree.examples;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/**
 * The README's library example is this class, whole (but for the package line), so that it compiles
 * as written; it runs on its bundled default scene: it hits, and prints the tree's statistics.
 * (.ci/readme-check builds the README's copy from an empty folder, as a user would.)
 */
class LibraryExampleTest {
    @Test void runsAsTheReadmeShows() throws Exception {
        PrintStream old = System.out;
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        try {
            System.setOut(new PrintStream(out, true));
            LibraryExample.main(new String[0]);
        } finally {
            System.setOut(old);
        }
        assertThat(out.toString()).startsWith("hit triangle ").contains("nodes: 33629", "expected cost: 210.75");
    }

    @Test void theReadmeQuotesTheWholeExample() throws Exception {
        String readme = Files.readString(Path.of("README.md"));
        String source = Files.readString(Path.of("src/main/java/org/kdtree/examples/LibraryExample.java"));
        String program = source.substring(source.indexOf('\n') + 1).strip();
        assertThat(readme).contains("```java\n" + program + "\n```");
    }
}
