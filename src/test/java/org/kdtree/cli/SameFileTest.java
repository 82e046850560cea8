package org.kdtree.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** One file by any spelling: relative, with {@code ..}, by symbolic link, by hard link. */
class SameFileTest {
    @TempDir Path dir;

    @Test void oneFileByEverySpelling() throws IOException {
        Path sub = Files.createDirectory(dir.resolve("sub"));
        Path file = Files.writeString(sub.resolve("pts.csv"), "0,0\n");
        assertThat(SameFile.same(file, sub.resolve("./pts.csv"))).isTrue();
        assertThat(SameFile.same(file, sub.resolve("../sub/pts.csv"))).isTrue();
        assertThat(SameFile.same(file, Path.of("").toAbsolutePath().relativize(file))).isTrue();
        assertThat(SameFile.same(file, Files.createSymbolicLink(dir.resolve("link.csv"), file))).isTrue();
        assertThat(SameFile.same(file, Files.createLink(dir.resolve("hard.csv"), file))).isTrue();
        Path linkedFolder = Files.createSymbolicLink(dir.resolve("folder-link"), sub);
        assertThat(SameFile.same(file, linkedFolder.resolve("pts.csv"))).isTrue();
    }

    @Test void differentFilesAndNewOnesAreNotTheSame() throws IOException {
        Path a = Files.writeString(dir.resolve("a.csv"), "0\n");
        Path copy = Files.writeString(dir.resolve("b.csv"), "0\n");
        assertThat(SameFile.same(a, copy)).isFalse();
        assertThat(SameFile.same(a, dir.resolve("new.csv"))).isFalse();
        assertThat(SameFile.same(dir.resolve("new.csv"), dir.resolve("./new.csv"))).isTrue();
    }
}
