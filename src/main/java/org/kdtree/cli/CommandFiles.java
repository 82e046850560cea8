package org.kdtree.cli;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Locale;
import org.kdtree.files.AtomicFile;
import org.kdtree.io.BundledScenes;
import org.kdtree.io.FileKind;
import org.kdtree.io.PrimitivesReader;
import org.kdtree.shape.PointsKd;
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

    /**
     * The file MESH names, found as {@code stats} and {@code render} find theirs: the file itself,
     * or a bundled scene ({@code scenes:clustered-spheres}, or {@code scenes/clustered-spheres.obj}
     * where no such file is here).
     */
    static Path meshFile(Path given) {
        return BundledScenes.resolve(given.toString());
    }

    /** The triangle mesh {@code command} traces rays through: an OBJ file (a bundled one too) with at least one triangle. */
    static TriangleMesh readMesh(Path given, String command) throws IOException {
        Path mesh = meshFile(given);
        requireNotFolder("MESH", given);
        if (!java.nio.file.Files.exists(mesh)) throw new IllegalArgumentException(given + ": no such file");
        PrimitivesReader.requireNotTree(mesh);
        if (FileKind.of(mesh) != FileKind.OBJ)
            throw new IllegalArgumentException(given + ": " + command + " traces rays through a triangle mesh; give an OBJ file (bundled: "
                    + String.join(", ", BundledScenes.FILES.stream().filter(f -> FileKind.of(f) == FileKind.OBJ)
                    .map(f -> BundledScenes.PREFIX + f.substring(0, f.length() - FileKind.OBJ.extension().length())).toList()) + ")");
        TriangleMesh m = PrimitivesReader.readMesh(mesh);
        if (m.size() == 0) throw new IllegalArgumentException(mesh + ": the mesh has no triangles (no 'f' lines)");
        return m;
    }

    /** The points of a k-NN command's POINTS file (CSV). */
    static PointsKd readPoints(Path pointsFile) throws IOException {
        return PrimitivesReader.readPoints(requireNotFolder("POINTS", pointsFile));
    }

    /** The query points of its {@code --queries} file (CSV), refused unless of the points' dimension. */
    static PointsKd readQueries(Path queriesFile, PointsKd points, Path pointsFile) throws IOException {
        PointsKd queries = PrimitivesReader.readPoints(requireNotFolder("--queries", queriesFile));
        if (queries.dimension() != points.dimension())
            throw new IllegalArgumentException(queriesFile + ": the queries are " + queries.dimension() + "-D, the points "
                    + points.dimension() + "-D (" + pointsFile + ")");
        return queries;
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
