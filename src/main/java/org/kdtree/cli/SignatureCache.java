package org.kdtree.cli;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.Arrays;
import java.util.HexFormat;
import org.kdtree.compare.TreeSignature;
import org.kdtree.files.AtomicFile;

/**
 * {@code similar}'s signatures, kept between runs in a cache folder of their own (not beside the
 * data: a data folder may be read-only or shared, and a second file per data set would clutter it
 * and be listed with the data). One entry per data file and builder, named by a hash of the
 * file's real path and the builder's settings; it holds the SHA-256 of the file's content when the
 * signature was made, so an entry whose file has changed since (by content, whatever its date) is
 * made again and replaced. An entry that cannot be read is made again; a cache that cannot be
 * written is said once and the search goes on without it.
 */
final class SignatureCache {
    /** The default folder: the user's cache ({@code $XDG_CACHE_HOME}, else {@code ~/.cache}), {@code kdtree/signatures}. */
    static Path defaultFolder() {
        String xdg = System.getenv("XDG_CACHE_HOME");
        Path base = xdg != null && !xdg.isBlank() ? Path.of(xdg) : Path.of(System.getProperty("user.home"), ".cache");
        return base.resolve("kdtree").resolve("signatures");
    }

    /** Makes a data file's signature when the cache has none for its content. */
    interface Maker {
        /** {@return the file's signature} */
        TreeSignature make() throws IOException;
    }

    private static final int HASH = 32;
    private final Path folder;
    private final String builder;
    private boolean writable = true;
    private int hits, made;

    /**
     * @param folder  the cache folder (made if missing)
     * @param builder the builder and its settings, in words: a signature is of a tree of one builder
     */
    SignatureCache(Path folder, String builder) {
        this.folder = folder;
        this.builder = builder;
    }

    /** {@return the file's signature}: from the cache if it holds one for this content and builder, else made (and kept) */
    TreeSignature get(Path file, Maker maker) throws IOException {
        byte[] content = contentHash(file);
        Path entry = folder.resolve(HexFormat.of().formatHex(sha256((file.toRealPath() + "\n" + builder).getBytes(StandardCharsets.UTF_8))) + ".sig");
        TreeSignature cached = read(entry, content);
        if (cached != null) {
            hits++;
            return cached;
        }
        TreeSignature s = maker.make();
        made++;
        write(entry, content, s);
        return s;
    }

    /** {@return the signatures read from the cache} */
    int hits() { return hits; }

    /** {@return the signatures made} */
    int made() { return made; }

    private static TreeSignature read(Path entry, byte[] content) {
        try {
            if (!Files.isRegularFile(entry)) return null;
            byte[] bytes = Files.readAllBytes(entry);
            if (bytes.length < HASH || !Arrays.equals(bytes, 0, HASH, content, 0, HASH)) return null;   // the file changed
            return TreeSignature.fromBytes(Arrays.copyOfRange(bytes, HASH, bytes.length));
        } catch (IOException | IllegalArgumentException damaged) {
            return null;   // made again, and the entry replaced
        }
    }

    private void write(Path entry, byte[] content, TreeSignature s) {
        if (!writable) return;
        try {
            Files.createDirectories(folder);
            byte[] signature = s.toBytes();
            AtomicFile.write(entry, out -> {
                out.write(content);
                out.write(signature);
            });
        } catch (IOException | SecurityException e) {
            writable = false;
            System.err.println("similar: note: cannot keep signatures in " + folder + " (" + e.getMessage() + "); going on without the cache");
        }
    }

    private static byte[] contentHash(Path file) throws IOException {
        MessageDigest d = digest();
        byte[] buffer = new byte[1 << 16];
        try (InputStream in = Files.newInputStream(file)) {
            for (int n; (n = in.read(buffer)) > 0; ) d.update(buffer, 0, n);
        }
        return d.digest();
    }

    private static byte[] sha256(byte[] bytes) {
        return digest().digest(bytes);
    }

    private static MessageDigest digest() {
        try {
            return MessageDigest.getInstance("SHA-256");
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("every Java platform has SHA-256", e);
        }
    }
}
