package org.kdtree.cli;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.kdtree.io.FileKind;
import org.kdtree.io.PrimitivesReader;
import org.kdtree.limits.Limits;
import org.kdtree.shape.PointsKd;
import org.kdtree.shape.Primitives;
import org.kdtree.shape.Scene2D;

/**
 * A data set as {@code compare-trees} and {@code similar} read it: a scene file by its kind
 * ({@code .obj}, {@code .scene2d}, {@code .json}), any other file as points in CSV (as {@code knn}
 * reads them); its kind of data (points, 2-D shapes or triangles), since only data of one kind
 * and dimension compare (the builder of their trees: {@link CompareOptions}).
 */
final class TreeData {
    private TreeData() {
    }

    /**
     * {@return the data of a file}, at least one primitive
     *
     * @param what how the command names the input (e.g. "A", "QUERY")
     * @throws IOException or IllegalArgumentException in one line naming the file
     */
    static Primitives read(String what, Path file) throws IOException {
        CommandFiles.requireNotFolder(what, file);
        if (!Files.exists(file)) throw new IllegalArgumentException(what + " " + file + ": no such file");
        Primitives p = FileKind.of(file) != null ? PrimitivesReader.read(file) : PrimitivesReader.readPoints(file);
        Limits.DIMENSION.check(what + " " + file + ": its dimension", p.dimension());
        if (p.size() == 0) throw new IllegalArgumentException(what + " " + file + ": " + kind(p) + " with nothing in it; a tree needs at least one");
        return p;
    }

    /** {@return the kind of data, in words}: what must agree between two compared sets besides the dimension */
    static String kind(Primitives p) {
        return p instanceof PointsKd ? "points" : p instanceof Scene2D ? "a 2-D scene" : "a triangle mesh";
    }

    /** {@return the size, kind and dimension in words}, e.g. "2000 5-D points" */
    static String describe(Primitives p) {
        return p instanceof PointsKd ? p.size() + " " + p.dimension() + "-D points"
                : kind(p) + " of " + p.size() + (p instanceof Scene2D ? " shapes" : " triangles");
    }

    /**
     * Refuses two data sets that do not compare: of other kinds or dimensions, in one line naming both files.
     */
    static void requireComparable(String whatA, Path a, Primitives pa, String whatB, Path b, Primitives pb) {
        if (!kind(pa).equals(kind(pb)) || pa.dimension() != pb.dimension())
            throw new IllegalArgumentException(whatB + " " + b + " is " + describe(pb) + ", " + whatA + " " + a + " " + describe(pa)
                    + ": only data of one kind and dimension compare");
    }
}
