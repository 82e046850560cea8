package org.kdtree.io;

import java.nio.file.Path;
import java.util.Locale;

/**
 * The scene files by extension, each with the one reader that fits it: a reader given another
 * kind of file says which reader reads it, instead of reading it wrong (a JSON scene as an OBJ
 * mesh of no triangles).
 */
final class FileKinds {
    static final String OBJ = ".obj", SCENE2D = ".scene2d", JSON = ".json";

    private FileKinds() {
    }

    /** {@return the kind of {@code file} by its extension: {@link #OBJ}, {@link #SCENE2D}, {@link #JSON}, or null} */
    static String of(Path file) {
        Path name = file.getFileName();
        if (name == null) return null;
        String n = name.toString().toLowerCase(Locale.ROOT);
        for (String k : new String[] {OBJ, SCENE2D, JSON}) if (n.endsWith(k)) return k;
        return null;
    }

    /**
     * Refuses a file whose extension says it is another kind than {@code expected}, naming the reader that fits it.
     *
     * @throws SceneFormatException naming the file, what it is and its reader
     */
    static void require(Path file, String expected) throws SceneFormatException {
        String kind = of(file);
        if (kind == null || kind.equals(expected)) return;
        throw new SceneFormatException(file.toString(), 0, describe(kind) + ", not " + describe(expected) + "; read it with " + reader(kind));
    }

    /** {@return what a file of that kind is} */
    static String describe(String kind) {
        return switch (kind) {
            case OBJ -> "an OBJ mesh";
            case SCENE2D -> "a 2-D scene (.scene2d)";
            default -> "a JSON render scene";
        };
    }

    /** {@return the reader of that kind, as a library user calls it} */
    static String reader(String kind) {
        return switch (kind) {
            case OBJ -> "ObjMeshReader.read (any scene's primitives: PrimitivesReader.read)";
            case SCENE2D -> "Scene2DReader.read (any scene's primitives: PrimitivesReader.read)";
            default -> "SceneReader.read (its triangles: PrimitivesReader.readMesh)";
        };
    }
}
