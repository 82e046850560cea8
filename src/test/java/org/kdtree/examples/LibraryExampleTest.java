package org.kdtree.examples;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/** The README's library example compiles (it is this class's neighbour) and runs: it hits, and prints the tree's statistics. */
class LibraryExampleTest {
    @Test void runsAsTheReadmeShows() throws Exception {
        PrintStream old = System.out;
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        try {
            System.setOut(new PrintStream(out, true));
            LibraryExample.main(new String[] {"scenes/clustered-spheres.obj"});
        } finally {
            System.setOut(old);
        }
        assertThat(out.toString()).startsWith("hit triangle ").contains("nodes: 33629", "expected cost: 210.75");
    }

    @Test void theReadmeQuotesTheExampleAsItIs() throws Exception {
        String readme = Files.readString(Path.of("README.md"));
        String source = Files.readString(Path.of("src/main/java/org/kdtree/examples/LibraryExample.java"));
        String body = source.substring(source.indexOf("        TriangleMesh mesh"), source.indexOf("        System.out.println(tree.stats()"));
        for (String line : body.split("\n")) assertThat(readme).as("README quotes: %s", line.strip()).contains(line.strip());
    }
}
