package org.kdtree.cli;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Whether two paths name one file, however spelt: {@code x}, {@code ./x}, {@code ../dir/x}, a
 * symbolic link to it, or a hard link of it. Used to refuse an output that would overwrite an
 * input before any work is done.
 */
final class SameFile {
    private SameFile() {
    }

    /**
     * {@return whether {@code a} and {@code b} are one file}: by the file system's identity when
     * both exist ({@link Files#isSameFile}, which sees hard links), otherwise by their real paths
     * (an output that does not exist yet is the same file as nothing that does).
     *
     * @param a one path
     * @param b the other
     */
    static boolean same(Path a, Path b) {
        try {
            if (Files.exists(a) && Files.exists(b)) return Files.isSameFile(a, b);
        } catch (IOException unreadable) {
            // fall through to the names: an unreadable file is compared by where it is
        }
        return real(a).equals(real(b));
    }

    /** The path with its existing part resolved (links, {@code ..}), the rest normalised. */
    private static Path real(Path p) {
        Path absolute = p.toAbsolutePath().normalize();
        Path existing = absolute;
        while (existing != null && !Files.exists(existing)) existing = existing.getParent();
        if (existing == null) return absolute;
        try {
            return existing.toRealPath().resolve(existing.relativize(absolute)).normalize();
        } catch (IOException unreadable) {
            return absolute;
        }
    }
}
