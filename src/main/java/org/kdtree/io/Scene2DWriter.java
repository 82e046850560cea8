package org.kdtree.io;

import java.io.IOException;
import java.io.Writer;
import java.nio.file.Path;
import org.kdtree.files.AtomicFile;
import org.kdtree.shape.Scene2D;
import org.kdtree.shape.Shape2D;

/** Writes a 2-D scene in the {@code .scene2d} format that {@link Scene2DReader} reads (the workbench's File > Save). */
public final class Scene2DWriter {
    private Scene2DWriter() {
    }

    /**
     * Writes the shapes in the format {@link Scene2DReader#read(Path)} accepts.
     *
     * @param scene the shapes
     * @param out receives the text
     * @throws IOException if writing fails
     */
    public static void write(Scene2D scene, Writer out) throws IOException {
        for (Shape2D s : scene.shapes()) {
            StringBuilder b = new StringBuilder(s.keyword());
            for (double c : s.coords()) b.append(' ').append(format(c));
            out.write(b.append('\n').toString());
        }
        out.flush();
    }

    /**
     * Writes the shapes to a file in the format {@link Scene2DReader#read(Path)} accepts.
     *
     * @param scene the shapes
     * @param file the file, replaced whole if it exists ({@link AtomicFile})
     * @throws IOException if writing fails; the file is then left as it was
     */
    public static void write(Scene2D scene, Path file) throws IOException {
        AtomicFile.writeText(file, w -> write(scene, w));
    }

    private static String format(double c) {
        return c == Math.rint(c) && Math.abs(c) < 1e15 ? Long.toString((long) c) : Double.toString(c);
    }
}
