package org.kdtree.io;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Locale;
import org.kdtree.shape.Primitives;

/**
 * Reads the primitives of a file by its extension: {@code .obj} meshes, {@code .scene2d} 2-D
 * scenes and {@code .json} render scenes (their triangles).
 */
public final class PrimitivesReader {
    private PrimitivesReader() {
    }

    /**
     * {@return the primitives of an {@code .obj}, {@code .scene2d} or {@code .json} scene file}
     *
     * @param file the file
     * @throws IOException if the file cannot be read, is malformed or has another extension
     */
    public static Primitives read(Path file) throws IOException {
        String name = file.getFileName().toString().toLowerCase(Locale.ROOT);
        if (name.endsWith(".obj")) return ObjMeshReader.read(file);
        if (name.endsWith(".scene2d")) return Scene2DReader.read(file);
        if (name.endsWith(".json")) return SceneReader.read(file).mesh();
        throw new SceneFormatException(file.toString(), 0, "unknown file type (expected .obj, .scene2d or .json)");
    }
}
