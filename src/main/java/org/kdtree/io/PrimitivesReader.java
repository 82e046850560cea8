package org.kdtree.io;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Locale;
import org.kdtree.scene.Scene;
import org.kdtree.shape.PointsKd;
import org.kdtree.shape.Primitives;
import org.kdtree.shape.Scene2D;
import org.kdtree.shape.TriangleMesh;

/**
 * Every file the library reads, read by its kind ({@link FileKind}): the primitives of
 * {@code .obj} meshes, {@code .scene2d} 2-D scenes and {@code .json} render scenes (their
 * triangles), a render scene whole, and point sets ({@code .csv}). The one door to the readers of
 * this package: each format has one reader, and every command and the workbench come through here.
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
        requireExists(file);
        FileKind kind = FileKind.of(file);
        if (kind != null && !java.nio.file.Files.isDirectory(file)) {
            return switch (kind) {
                case OBJ -> ObjMeshReader.read(file);
                case SCENE2D -> Scene2DReader.read(file);
                case JSON -> SceneReader.read(file).mesh();
            };
        }
        throw new SceneFormatException(file.toString(), 0, java.nio.file.Files.isDirectory(file)
                ? "is a folder, not a scene file (.obj, .scene2d or .json)" : "unknown file type (expected .obj, .scene2d or .json)");
    }

    /**
     * {@return the triangles of an {@code .obj} mesh or a {@code .json} render scene}, at least one
     *
     * @param file the file (a bundled one too: {@link BundledScenes#resolve})
     * @throws IOException if the file cannot be read or is malformed, is a 2-D scene (which has
     *         no triangles), has another extension, or holds no triangle
     */
    public static TriangleMesh readMesh(Path file) throws IOException {
        return mesh(file);
    }

    /** What {@link #readScene} makes of a bare OBJ mesh, in words, for a user to see. */
    public static final String BARE_MESH = MeshScene.DESCRIPTION;

    /**
     * {@return the render scene of a {@code .json} file}: camera, lights, materials and the
     * triangles of its objects (OBJ files it names are read relative to it); or of a bare
     * {@code .obj} mesh, framed and lit as {@link #BARE_MESH} says
     *
     * @param file the scene file (a bundled one too: {@link BundledScenes#resolve})
     * @throws IOException if it cannot be read or is malformed, naming the file, line and field
     */
    public static Scene readScene(Path file) throws IOException {
        requireExists(file);
        return FileKind.of(file) == FileKind.OBJ ? MeshScene.read(file) : SceneReader.read(file);
    }

    /**
     * {@return the 2-D scene of a {@code .scene2d} file}
     *
     * @param file the file
     * @throws IOException if it cannot be read or is malformed, naming the file and line
     */
    public static Scene2D readScene2D(Path file) throws IOException {
        requireNotTree(file);
        return Scene2DReader.read(file);
    }

    /**
     * {@return the points of a CSV file}: one point per line, comma-separated coordinates; blank
     * lines and lines starting with {@code #} are skipped
     *
     * @param file the file
     * @throws IOException if it cannot be read or is malformed, naming the file and line
     */
    public static PointsKd readPoints(Path file) throws IOException {
        requireNotTree(file);
        return PointCsvReader.read(file);
    }

    private static TriangleMesh mesh(Path file) throws IOException {
        requireExists(file);
        FileKind kind = FileKind.of(file);
        if (kind == FileKind.OBJ) return ObjMeshReader.read(file);
        if (kind == FileKind.SCENE2D)
            throw new SceneFormatException(file.toString(), 0, "a 2-D scene (.scene2d) has no triangles; give an .obj mesh or a .json scene");
        if (kind != FileKind.JSON)
            throw new SceneFormatException(file.toString(), 0, "unknown file type (expected an .obj mesh or a .json scene)");
        TriangleMesh m = SceneReader.read(file).mesh();
        if (m.size() == 0) throw new SceneFormatException(file.toString(), 0, "the scene has no triangles");
        return m;
    }

    /** A missing file is "no such file", whatever its name, as every reader says it (not "unknown file type"); a saved tree is named. */
    static void requireExists(Path file) throws IOException {
        if (!java.nio.file.Files.exists(file)) throw new SceneFormatException(file.toString(), 0, "no such file");
        requireNotTree(file);
    }

    /**
     * Refuses a saved tree given where a scene or points are due, naming it as one whatever its
     * name (rather than reporting a line of binary), as every reader here does.
     *
     * @param file the file given as a scene
     * @throws IOException naming the file as a saved tree, or if it cannot be read
     */
    public static void requireNotTree(Path file) throws IOException {
        if (org.kdtree.treefile.TreeFile.isTreeFile(file))
            throw new SceneFormatException(file.toString(), 0, "is a saved tree (--save-tree), not a scene or point file: give the "
                    + "scene it was built over, and this file with --tree");
    }
}
