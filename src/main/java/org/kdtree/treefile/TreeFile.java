package org.kdtree.treefile;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import org.kdtree.accel.AccelerationStructure;
import org.kdtree.files.AtomicFile;
import org.kdtree.shape.Primitives;
import org.kdtree.spec.BuilderSpec;

/**
 * Saving a built tree and loading it again, the door to this package: build once (the exact
 * SAH's seconds), query many times (a load's milliseconds). A file holds a kd-tree (over
 * triangles, 2-D shapes or k-D points) or a bounding volume hierarchy, the builder and settings
 * that made it, its statistics and the fingerprint of the primitives it was built over; a load
 * refuses, in one line, a file that is not a tree file, of another format version, larger than
 * {@link org.kdtree.limits.Limits#TREE_FILE}, truncated, damaged (its checksum), or built over
 * other primitives than those it is loaded over. The layout is docs/tree-files.md.
 */
public final class TreeFile {
    /** The extension the documentation gives tree files (any name is read; the content decides). */
    public static final String EXTENSION = ".kdtree";

    private TreeFile() {
    }

    /**
     * Saves {@code tree} to {@code file}, whole or not at all ({@link AtomicFile}).
     *
     * @param file       the file to write
     * @param tree       a structure {@code spec} built over {@code primitives}
     * @param spec       the builder and settings it was built with
     * @param primitives the primitives it was built over (their fingerprint is saved)
     * @throws IOException if the file cannot be written
     * @throws IllegalArgumentException if the tree is not of the primitives' dimension
     */
    public static void save(Path file, AccelerationStructure tree, BuilderSpec spec, Primitives primitives) throws IOException {
        AtomicFile.write(file, out -> write(out, tree, spec, primitives));
    }

    /**
     * Writes {@code tree} to a stream (not closed).
     *
     * @param out        where the file's bytes go
     * @param tree       a structure {@code spec} built over {@code primitives}
     * @param spec       the builder and settings it was built with
     * @param primitives the primitives it was built over (their fingerprint is saved)
     * @throws IOException if the stream fails
     */
    public static void write(OutputStream out, AccelerationStructure tree, BuilderSpec spec, Primitives primitives) throws IOException {
        TreeFileWriter.write(out, tree, spec, primitives);
    }

    /**
     * Loads the tree of {@code file} over {@code primitives}, which must be those it was built over.
     *
     * @param file       a file {@link #save} wrote
     * @param primitives the scene's primitives
     * @return the tree, its builder and settings, its statistics
     * @throws TreeFileException naming the file and what is wrong with it, in one line
     * @throws IOException if the file cannot be read
     */
    public static SavedTree load(Path file, Primitives primitives) throws IOException {
        if (!Files.isRegularFile(file))
            throw new TreeFileException(file.toString(), Files.isDirectory(file) ? "is a folder, not a tree file" : "no such file");
        return TreeFileReader.read(file, primitives);
    }

    /**
     * Reads a tree from a stream over {@code primitives}, which must be those it was built over.
     *
     * @param in         the bytes {@link #write} wrote (read up to the length they state)
     * @param name       what to call the stream in errors
     * @param primitives the scene's primitives
     * @return the tree, its builder and settings, its statistics
     * @throws TreeFileException naming the stream and what is wrong with its bytes, in one line
     * @throws IOException if the stream fails
     */
    public static SavedTree read(InputStream in, String name, Primitives primitives) throws IOException {
        return TreeFileReader.read(in, name, primitives);
    }

    /**
     * {@return whether {@code file} starts as a tree file does} (the scene readers refuse one in one line)
     *
     * @param file any file
     * @throws IOException if it cannot be read
     */
    public static boolean isTreeFile(Path file) throws IOException {
        if (!Files.isRegularFile(file)) return false;
        try (InputStream in = Files.newInputStream(file)) {
            return TreeFileReader.isTreeFile(in.readNBytes(TreeFormat.MAGIC.length));
        }
    }
}
