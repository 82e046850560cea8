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
        Path temporary;
        try {
            temporary = temporaryBeside(target);
        } catch (IOException e) {
            throw new IOException(target + ": " + reason(e, target), e);
        }
        try {
            try (OutputStream out = new BufferedOutputStream(Files.newOutputStream(temporary))) {
                content.writeTo(out);
            }
            try {
                moveOnto(temporary, target);
            } catch (IOException e) {
                throw new IOException(target + ": " + reason(e, target), e);
            }
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

    /**
     * Checks, before any work goes into it, that {@code target} can be written: that it is no
     * folder, that its folder exists, and that a file can be made in that folder (as
     * {@link #write} will make its temporary there). Nothing is left behind.
     *
     * @param target the file a command or a study will write
     * @throws IOException if it cannot be written; the message is the target as given, a colon
     *         and the reason ("permission denied: ...", "is a folder, not a file", ...)
     */
    public static void requireWritable(Path target) throws IOException {
        Path absolute = followLink(target.toAbsolutePath());
        if (Files.isDirectory(absolute)) throw new IOException(target + ": is a folder, not a file; give a file name");
        Path folder = absolute.getParent();
        if (folder == null || !Files.exists(folder)) throw new IOException(target + ": the folder " + folder + " does not exist");
        if (!Files.isDirectory(folder)) throw new IOException(target + ": " + folder + " is a file, not a folder");
        Path probe;
        try {
            probe = temporaryBeside(target);
        } catch (IOException e) {
            throw new IOException(target + ": " + reason(e, target), e);
        }
        Files.deleteIfExists(probe);
    }

    /** Why writing {@code target} failed, in words, without the temporary file's name. */
    private static String reason(IOException e, Path target) {
        Path folder = target.toAbsolutePath().getParent();
        boolean denied = e instanceof java.nio.file.AccessDeniedException
                || e instanceof java.nio.file.FileSystemException f && "Operation not permitted".equalsIgnoreCase(f.getReason());
        if (denied)
            return "permission denied (no file can be written in " + folder + ")";
        if (e instanceof java.nio.file.FileSystemException f && f.getReason() != null) {
            String why = f.getReason();
            if (why.equalsIgnoreCase("Is a directory")) return "is a folder, not a file; give a file name";
            if (why.equalsIgnoreCase("Read-only file system")) return "read-only file system (no file can be written in " + folder + ")";
            return why.substring(0, 1).toLowerCase(java.util.Locale.ROOT) + why.substring(1);
        }
        return e.getMessage() != null ? e.getMessage() : e.toString();
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
