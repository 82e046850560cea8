package org.kdtree.files;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.IOException;
import java.io.InterruptedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** A file is written whole or not at all: failures keep the old file, writers never mix, no temporary stays. */
class AtomicFileTest {
    @TempDir Path dir;

    private List<Path> folder() throws IOException {
        try (Stream<Path> files = Files.list(dir)) {
            return files.sorted().toList();
        }
    }

    @Test void writesAndReplacesAFileLeavingNothingElse() throws IOException {
        Path target = dir.resolve("out.csv");
        AtomicFile.writeString(target, "first\n");
        AtomicFile.writeText(target, w -> w.write("second, é\n"));
        assertThat(Files.readString(target)).isEqualTo("second, é\n");
        assertThat(folder()).containsExactly(target);
    }

    /** A writer that fails (or is interrupted) halfway: the old bytes stay, the temporary goes. */
    @Test void aFailureMidwayKeepsTheOldFileByteForByte() throws IOException {
        Path target = dir.resolve("hits.txt");
        byte[] old = "0.5 3\nmiss\n".getBytes(StandardCharsets.UTF_8);
        Files.write(target, old);
        for (IOException failure : List.of(new IOException("disk full"), new InterruptedIOException("interrupted"))) {
            assertThatThrownBy(() -> AtomicFile.write(target, out -> {
                out.write(new byte[100_000]); // past any buffer: the temporary really holds part of it
                throw failure;
            })).isSameAs(failure);
            assertThat(Files.readAllBytes(target)).isEqualTo(old);
            assertThat(folder()).containsExactly(target);
        }
        RuntimeException bug = new IllegalStateException("the content's own bug");
        assertThatThrownBy(() -> AtomicFile.writeText(target, w -> {
            w.write("partial line");
            throw bug;
        })).isSameAs(bug);
        assertThat(Files.readAllBytes(target)).isEqualTo(old);
        assertThat(folder()).containsExactly(target);
    }

    @Test void aFolderThatIsMissingIsAnIOException() {
        assertThatThrownBy(() -> AtomicFile.writeString(dir.resolve("no/such/folder/x.csv"), "x"))
                .isInstanceOf(IOException.class);
    }

    /** Eight writers of one file at once, many times: the file is always one writer's content, whole. */
    @Test void concurrentWritersNeverMix() throws Exception {
        Path target = dir.resolve("same.csv");
        int writers = 8, rounds = 20, lines = 20_000;
        ExecutorService pool = Executors.newFixedThreadPool(writers);
        try {
            for (int round = 0; round < rounds; round++) {
                CountDownLatch start = new CountDownLatch(1);
                List<Future<?>> done = new ArrayList<>();
                for (int w = 0; w < writers; w++) {
                    String line = "writer " + w + "\n";
                    done.add(pool.submit(() -> {
                        start.await();
                        AtomicFile.writeText(target, out -> {
                            for (int i = 0; i < lines; i++) out.write(line);
                        });
                        return null;
                    }));
                }
                start.countDown();
                for (Future<?> f : done) f.get();
                List<String> written = Files.readAllLines(target);
                assertThat(written).hasSize(lines);
                assertThat(written.stream().distinct()).as("round " + round).hasSize(1);
                assertThat(folder()).containsExactly(target);
            }
        } finally {
            pool.shutdownNow();
        }
    }

    /** A symbolic link stays a link: the file it points to gets the new content. */
    @Test void writingThroughASymbolicLinkReplacesItsTarget() throws IOException {
        Path real = Files.writeString(dir.resolve("real.csv"), "old");
        Path link = Files.createSymbolicLink(dir.resolve("link.csv"), real);
        AtomicFile.writeString(link, "new");
        assertThat(Files.isSymbolicLink(link)).isTrue();
        assertThat(Files.readString(real)).isEqualTo("new");
    }
}
