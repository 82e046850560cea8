package org.kdtree.architecture;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * Issue 45: a structure's traversal loops are listed here, so that none is added without being
 * seen. A loop is a source file of the structure's package (and of src/vector) that keeps a stack
 * of nodes and takes rays.
 */
class TraversalLoopsTest {
    private static final Pattern STACK = Pattern.compile("stackNode|int\\[\\] stack|TraversalStack");
    private static final Pattern RAYS = Pattern.compile("\\bRay \\w|RayPacket");

    @Test void theKdTreeHasThreeLoopsTheListeningOneTheSilentOneAndThePacketLoop() throws IOException {
        assertThat(loops("kdtree")).containsExactly("MeshTraversal", "PacketTraversal", "Traverser");
    }

    /** The listening loop, the single-ray loop and the packet loop; src/vector holds their Vector API kernels only. */
    @Test void theBvhHasThreeLoopsTheListeningOneTheSingleRayOneAndThePacketLoop() throws IOException {
        assertThat(loops("bvh")).containsExactly("BvhTraverser", "PacketTraversal", "WideTraversal");
    }

    private static List<String> loops(String pkg) throws IOException {
        try (Stream<Path> main = Files.list(Path.of("src/main/java/org/kdtree", pkg));
             Stream<Path> vector = Files.exists(Path.of("src/vector/java/org/kdtree", pkg))
                     ? Files.list(Path.of("src/vector/java/org/kdtree", pkg)) : Stream.empty()) {
            return Stream.concat(main, vector).filter(f -> f.toString().endsWith(".java")).filter(TraversalLoopsTest::isLoop)
                    .map(f -> f.getFileName().toString().replace(".java", "")).sorted().toList();
        }
    }

    private static boolean isLoop(Path f) {
        try {
            String s = Files.readString(f);
            return STACK.matcher(s).find() && RAYS.matcher(s).find();
        } catch (IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }
}
