package org.kdtree.io;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringReader;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Random;
import java.util.concurrent.atomic.AtomicLong;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.lifecycle.AfterContainer;
import org.junit.jupiter.api.Assertions;
import org.kdtree.cli.RayFileAccess;
import org.kdtree.kdtree.SahBuilder;
import org.kdtree.shape.InvalidGeometryException;

/**
 * Mutated files for every reader of the project's formats (OBJ, MTL, JSON scene, .scene2d and the
 * ray file of {@code raycast --rays}): each input is read, and, where it reads, its geometry is
 * built. The only acceptable failures are the project's own one-line errors
 * ({@link org.kdtree.io.SceneFormatException} and the other I/O errors that name the file, and
 * {@link InvalidGeometryException}); anything else (a {@code NumberFormatException} leaking from
 * a parser, say), or an input that takes more than 10 seconds, fails the test.
 *
 * <p>CI runs jqwik's default number of tries per format. On demand, run it longer, for example
 * ten minutes' worth: {@code mvn test -Dtest=ReadersFuzzTest -Djqwik.tries.default=200000}.
 */
class ReadersFuzzTest {
    private static final AtomicLong INPUTS = new AtomicLong();
    private static final Duration PER_INPUT = Duration.ofSeconds(10);

    private static final String OBJ = "# a mesh\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 1\nvt 0 0\nvn 0 0 1\n"
            + "f 1 2 3\nf 2/1 3/1 4/1\nf -1 -2 -3\nf 1//1 2//1 3//1 4//1\n";
    private static final String MTL = "newmtl red\nKd 1 0 0\nKs 0.5 0.5 0.5\nNs 20\nillum 2\n\nnewmtl glass\nNi 1.5\nTf 0.9 0.9 0.9\nillum 7\n";
    private static final String SCENE2D = "# shapes\nrect 0 0 1 1\ntriangle 2 0 3 0 2 1\nsegment 0 2 3 3\npoint 1.5 1.5\n";
    private static final String RAYS = "# rays\n0.2 0.2 -1 0 0 1\n0.5 0.5 2 0 0 -1 0 10\n0 0 0 1 1 1\n";

    @Property void obj(@ForAll long seed) throws Exception {
        read(seed, OBJ, ".obj", file -> new SahBuilder().build(ObjMeshReader.read(file)));
    }

    @Property void mtl(@ForAll long seed) throws Exception {
        read(seed, MTL, ".mtl", MaterialReader::read);
    }

    @Property void scene2d(@ForAll long seed) throws Exception {
        read(seed, SCENE2D, ".scene2d", file -> new SahBuilder().build(Scene2DReader.read(file)));
    }

    @Property void jsonScene(@ForAll long seed) throws Exception {
        read(seed, Files.readString(Path.of("scenes/cornell-box.json")), ".json", SceneReader::read);
    }

    @Property void rayFile(@ForAll long seed) throws Exception {
        read(seed, RAYS, ".rays", file -> RayFileAccess.trace(new BufferedReader(new StringReader(Files.readString(file,
                StandardCharsets.ISO_8859_1))), file.toString(), new PrintWriter(new StringWriter())));
    }

    @AfterContainer
    static void report() {
        System.out.println("ReadersFuzzTest: " + INPUTS.get() + " mutated inputs read");
    }

    interface Reader {
        void read(Path file) throws Exception;
    }

    private static void read(long seed, String seedText, String suffix, Reader reader) throws Exception {
        byte[] input = Mutator.mutate(seedText.getBytes(StandardCharsets.UTF_8), new Random(seed));
        Path file = Files.createTempFile("fuzz-", suffix);
        try {
            Files.write(file, input);
            INPUTS.incrementAndGet();
            Assertions.assertTimeoutPreemptively(PER_INPUT, () -> {
                try {
                    reader.read(file);
                } catch (IOException | InvalidGeometryException expected) {
                    assertThat(expected.getMessage()).as("the error says something").isNotBlank();
                }
            }, () -> "no answer within " + PER_INPUT + " for " + new String(input, StandardCharsets.ISO_8859_1));
        } finally {
            Files.deleteIfExists(file);
        }
    }
}
