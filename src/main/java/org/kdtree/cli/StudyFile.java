package org.kdtree.cli;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.kdtree.files.AtomicFile;

/**
 * A study's CSV, written as its rows come: after each finished row, all rows so far go to
 * {@code FILE.partial} beside the user's file, so that a study stopped midway (interrupted,
 * killed, failed) keeps what it measured without touching {@code FILE}; the complete table then
 * replaces {@code FILE} and the partial file is removed.
 */
final class StudyFile {
    private final Path target;
    private final Path partial;

    StudyFile(Path target) {
        this.target = target;
        this.partial = target.resolveSibling(target.getFileName() + ".partial");
    }

    /** {@return the partial file, which holds the finished rows until the table is complete} */
    Path partial() {
        return partial;
    }

    /** Keeps the rows finished so far in the partial file. */
    void progress(String csvSoFar) throws IOException {
        AtomicFile.writeString(partial, csvSoFar);
    }

    /** Writes the complete table in place of the user's file and drops the partial one. */
    void finish(String csv) throws IOException {
        AtomicFile.writeString(target, csv);
        Files.deleteIfExists(partial);
    }
}
