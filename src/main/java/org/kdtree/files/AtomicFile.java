package org.kdtree.files;

import java.io.BufferedOutputStream;
import java.io.BufferedWriter;
import java.io.IOException;
import java.io.OutputStream;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.FileSystems;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.attribute.FileAttribute;
import java.nio.file.attribute.PosixFilePermission;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.Set;

/**
 * The one way the library writes a file: the content goes to a temporary file in the target's
 * folder, which is then moved onto the target in one step. An error or an interruption while
 * writing leaves an existing target exactly as it was and removes the temporary; two writers of
 * one target never mix, the last to finish wins whole.
 *
 * <p>The move is atomic ({@link StandardCopyOption#ATOMIC_MOVE}); only where the file system
 * cannot move atomically does it fall back to replacing the target, which is still never a
 * mixture of two writers.
 */
public final class AtomicFile {
    /** What a new file's mode asks for; the process's umask takes its share, as for any new file. */
    private static final Set<PosixFilePermission> NEW_FILE = PosixFilePermissions.fromString("rw-rw-rw-");

    /** Writes a file's content to a stream, which the caller opened and will close. */
    @FunctionalInterface
    public interface Content {
        /**
         * Writes the whole content.
         *
         * @param out where it goes (buffered; do not close it)
         * @throws IOException if writing fails; the target is then left as it was
         */
        void writeTo(OutputStream out) throws IOException;
    }

    /** Writes a text file's content, as UTF-8. */
    @FunctionalInterface
    public interface Text {
        /**
         * Writes the whole text.
         *
         * @param out where it goes (buffered, UTF-8; do not close it)
         * @throws IOException if writing fails; the target is then left as it was
         */
        void writeTo(Writer out) throws IOException;
    }

    private AtomicFile() {
    }

    /**
     * Writes {@code target} whole or not at all.
     *
     * @param target the file to write (its folder must exist)
     * @param content what goes in it
     * @throws IOException if the content or the file system fails; {@code target} is unchanged
     */
    public static void write(Path target, Content content) throws IOException {
        Path temporary = temporaryBeside(target);
        try {
            try (OutputStream out = new BufferedOutputStream(Files.newOutputStream(temporary))) {
                content.writeTo(out);
            }
            moveOnto(temporary, target);
        } catch (Throwable failure) {
            Files.deleteIfExists(temporary);
            throw failure;
        }
    }

    /**
     * Writes a text file, UTF-8, whole or not at all.
     *
     * @param target the file to write (its folder must exist)
     * @param text what goes in it
     * @throws IOException if the text or the file system fails; {@code target} is unchanged
     */
    public static void writeText(Path target, Text text) throws IOException {
        write(target, out -> {
            Writer w = new BufferedWriter(new OutputStreamWriter(out, StandardCharsets.UTF_8));
            text.writeTo(w);
            w.flush();
        });
    }

    /**
     * Writes {@code text} to {@code target}, UTF-8, whole or not at all.
     *
     * @param target the file to write (its folder must exist)
     * @param text its whole content
     * @throws IOException if the file system fails; {@code target} is unchanged
     */
    public static void writeString(Path target, String text) throws IOException {
        writeText(target, out -> out.write(text));
    }

    /** A new, uniquely named file in the target's folder (a move within one folder can be atomic). */
    private static Path temporaryBeside(Path target) throws IOException {
        Path absolute = followLink(target.toAbsolutePath());
        Path folder = absolute.getParent();
        String prefix = "." + absolute.getFileName() + ".";
        boolean posix = FileSystems.getDefault().supportedFileAttributeViews().contains("posix")
                && folder.getFileSystem() == FileSystems.getDefault();
        if (!posix) return Files.createTempFile(folder, prefix, ".tmp");
        Set<PosixFilePermission> mode = Files.exists(absolute) ? Files.getPosixFilePermissions(absolute) : NEW_FILE;
        FileAttribute<Set<PosixFilePermission>> attribute = PosixFilePermissions.asFileAttribute(mode);
        return Files.createTempFile(folder, prefix, ".tmp", attribute);
    }

    /** A symbolic link stays a link: the file it points to is the one replaced. */
    private static Path followLink(Path target) {
        try {
            return Files.isSymbolicLink(target) ? target.toRealPath() : target;
        } catch (IOException dangling) {
            return target;
        }
    }

    private static void moveOnto(Path temporary, Path target) throws IOException {
        target = followLink(target.toAbsolutePath());
        try {
            Files.move(temporary, target, StandardCopyOption.ATOMIC_MOVE);
        } catch (AtomicMoveNotSupportedException notHere) {
            Files.move(temporary, target, StandardCopyOption.REPLACE_EXISTING);
        }
    }
}
