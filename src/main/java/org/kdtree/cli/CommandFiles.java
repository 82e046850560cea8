package org.kdtree.cli;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Locale;
import org.kdtree.files.AtomicFile;
import org.kdtree.io.FileKind;
import org.kdtree.io.PrimitivesReader;
import org.kdtree.shape.TriangleMesh;

/** The files the commands read and write, checked before any work so that a mistake costs one line, not a run. */
final class CommandFiles {
    private CommandFiles() {
    }

    /**
     * Refuses an input {@code what} (e.g. "MESH", "--queries") that is a folder, in the one
     * wording every command uses; a missing file is left to its reader, which names it.
     */
    static Path requireNotFolder(String what, Path file) {
        if (java.nio.file.Files.isDirectory(file))
            throw new IllegalArgumentException(what + " " + file + ": is a folder, not a file");
        return file;
    }

    /** The triangle mesh {@code command} traces rays through: an OBJ file with at least one triangle. */
    static TriangleMesh readMesh(Path mesh, String command) throws IOException {
        requireNotFolder("MESH", mesh);
        if (FileKind.of(mesh) != FileKind.OBJ)
            throw new IllegalArgumentException(mesh + ": " + command + " traces rays through a triangle mesh; give an OBJ file");
        TriangleMesh m = PrimitivesReader.readMesh(mesh);
        if (m.size() == 0) throw new IllegalArgumentException(mesh + ": the mesh has no triangles (no 'f' lines)");
        return m;
    }

    /**
     * Refuses, before any work, an output file of {@code option} that cannot be written: its
     * folder missing or not writable, or the file a folder; the line names the user's file and why.
     */
    static void requireWritable(String option, Path file) {
        try {
            AtomicFile.requireWritable(file);
        } catch (IOException e) {
            throw new IllegalArgumentException(option + " " + e.getMessage());
        }
    }

    /**
     * Refuses an output of {@code option} that is the input {@code input} (same file by any
     * spelling or link), before any work: writing it would destroy what the command reads.
     */
    static void requireNotInput(String option, Path output, String input, Path inputFile) {
        if (output != null && inputFile != null && SameFile.same(output, inputFile))
            throw new IllegalArgumentException(option + " " + output + " is the input " + input + " (" + inputFile
                    + "); write the results elsewhere");
    }
}
