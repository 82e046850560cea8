package org.kdtree.io;

import java.nio.file.Path;
import java.util.Locale;

/**
 * The scene files the project reads, each by its extension with the one reader that fits it:
 * the one registry from file kind to reader, which the readers, the commands and the workbench
 * all ask. A reader given another kind of file says which reader reads it, instead of reading it
 * wrong (a JSON scene as an OBJ mesh of no triangles).
 */
public enum FileKind {
    /** A Wavefront OBJ mesh: triangles, no camera. */
    OBJ(".obj", "an OBJ mesh", "ObjMeshReader.read (any scene's primitives: PrimitivesReader.read)", true, false),
    /** A 2-D scene of the workbench. */
    SCENE2D(".scene2d", "a 2-D scene (.scene2d)", "Scene2DReader.read (any scene's primitives: PrimitivesReader.read)", false, false),
    /** A JSON render scene: camera, lights, materials and objects. */
    JSON(".json", "a JSON render scene", "SceneReader.read (its triangles: PrimitivesReader.readMesh)", true, true);

    private final String extension, description, reader;
    private final boolean triangles, renders;

    FileKind(String extension, String description, String reader, boolean triangles, boolean renders) {
        this.extension = extension;
        this.description = description;
        this.reader = reader;
        this.triangles = triangles;
        this.renders = renders;
    }

    /**
     * {@return the kind of {@code file} by its extension, or null for none of these}
     *
     * @param file a file (its name decides)
     */
    public static FileKind of(Path file) {
        Path name = file.getFileName();
        return name == null ? null : of(name.toString());
    }

    /**
     * {@return the kind of the file named {@code name} by its extension, or null for none of these}
     *
     * @param name a file's name
     */
    public static FileKind of(String name) {
        String n = name.toLowerCase(Locale.ROOT);
        for (FileKind k : values()) if (n.endsWith(k.extension)) return k;
        return null;
    }

    /** {@return its extension with the dot}, e.g. {@code .obj} */
    public String extension() { return extension; }

    /** {@return its extension without the dot}, e.g. {@code obj}, as a file chooser's filter takes it */
    public String bareExtension() { return extension.substring(1); }

    /** {@return what a file of this kind is, in words}, e.g. "an OBJ mesh" */
    public String describe() { return description; }

    /** {@return the reader of this kind, as a library user calls it} */
    public String reader() { return reader; }

    /** {@return whether it holds 3-D triangles} (an OBJ mesh, a JSON scene's objects) */
    public boolean hasTriangles() { return triangles; }

    /** {@return whether it can be rendered as it is} (it has a camera and lights: a JSON scene) */
    public boolean renders() { return renders; }

    /**
     * Refuses a file whose extension says it is another kind than this, naming the reader that fits it.
     *
     * @param file the file
     * @throws SceneFormatException naming the file, what it is and its reader
     */
    void require(Path file) throws SceneFormatException {
        FileKind kind = of(file);
        if (kind == null || kind == this || !java.nio.file.Files.exists(file)) return;   // a missing file: the reader says "no such file"
        throw new SceneFormatException(file.toString(), 0, kind.describe() + ", not " + describe() + "; read it with " + kind.reader());
    }
}
