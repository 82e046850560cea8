package org.kdtree.testing;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import org.junit.jupiter.api.Assumptions;

/**
 * A folder no file can be written in, for tests of what a command says about an output it
 * cannot write: made read-only ({@code r-x}), and, where this process writes regardless (as
 * root), immutable ({@code chattr +i}). {@link #close} makes it writable again, so that the
 * test's temporary folder can be removed.
 */
public final class ReadOnlyFolder implements AutoCloseable {
    private final Path folder;
    private boolean immutable;

    private ReadOnlyFolder(Path folder) {
        this.folder = folder;
    }

    /**
     * Makes {@code dir/name} and takes its write permission away.
     *
     * @param dir a test's temporary folder
     * @param name the folder's name
     * @return the read-only folder; the test is skipped where no folder can be made read-only for this process
     * @throws Exception if the folder cannot be made
     */
    public static ReadOnlyFolder make(Path dir, String name) throws Exception {
        ReadOnlyFolder ro = new ReadOnlyFolder(Files.createDirectory(dir.resolve(name)));
        Files.setPosixFilePermissions(ro.folder, PosixFilePermissions.fromString("r-xr-xr-x"));
        if (!writable(ro.folder)) return ro;
        ro.immutable = new ProcessBuilder("chattr", "+i", ro.folder.toString()).inheritIO().start().waitFor() == 0;
        Assumptions.assumeFalse(writable(ro.folder), "this process writes in a read-only folder, and chattr +i failed");
        return ro;
    }

    /** {@return the folder} */
    public Path path() {
        return folder;
    }

    private static boolean writable(Path folder) {
        try {
            Files.delete(Files.createTempFile(folder, "probe", ".tmp"));
            return true;
        } catch (IOException e) {
            return false;
        }
    }

    @Override public void close() throws Exception {
        if (immutable) new ProcessBuilder("chattr", "-i", folder.toString()).inheritIO().start().waitFor();
        Files.setPosixFilePermissions(folder, PosixFilePermissions.fromString("rwxr-xr-x"));
    }
}
