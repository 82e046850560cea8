package org.kdtree.io;

import java.io.IOException;
import java.io.Reader;
import java.io.StringReader;
import java.io.Writer;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.kdtree.files.AtomicFile;
import org.kdtree.shape.Shape2D;
import org.kdtree.shape.Shapes2D;

/**
 * The 2-D scene format of the workbench: one shape per line, {@code #} starts a comment.
 * <pre>
 * point    x y
 * segment  x0 y0 x1 y1
 * rect     x0 y0 x1 y1          (two opposite corners)
 * triangle ax ay bx by cx cy
 * </pre>
 * Files end in {@code .scene2d}. See docs/scene-format.md.
 */
public final class Scene2DFormat {
    private Scene2DFormat() {
    }

    /**
     * {@return the shapes of a {@code .scene2d} file}
     *
     * @param file the file
     * @throws IOException if the file cannot be read or is malformed
     */
    public static Shapes2D read(Path file) throws IOException {
        try (TextLines lines = TextLines.open(file)) {
            return read(lines);
        }
    }

    /**
     * {@return the shapes of 2-D scene text}
     *
     * @param text the text
     * @param name used in error messages
     * @throws SceneFormatException if the text is malformed
     */
    public static Shapes2D parse(String text, String name) throws SceneFormatException {
        try {
            return read(new StringReader(text), name);
        } catch (SceneFormatException e) {
            throw e;
        } catch (IOException e) {
            throw new IllegalStateException(e);
        }
    }

    /**
     * {@return the shapes of 2-D scene text}
     *
     * @param reader the text
     * @param name used in error messages
     * @throws IOException if the text cannot be read or is malformed
     */
    public static Shapes2D read(Reader reader, String name) throws IOException {
        return read(TextLines.of(reader, name));
    }

    private static Shapes2D read(TextLines in) throws IOException {
        String name = in.name();
        List<Shape2D> shapes = new ArrayList<>();
        for (String line = in.next(); line != null; line = in.next()) {
            int lineNo = in.line();
            int hash = line.indexOf('#');
            String s = (hash >= 0 ? line.substring(0, hash) : line).strip();
            if (s.isEmpty()) continue;
            String[] t = s.split("\\s+");
            shapes.add(shape(t, name, lineNo));
        }
        return new Shapes2D(shapes);
    }

    private static Shape2D shape(String[] t, String name, int line) throws SceneFormatException {
        String kw = t[0].toLowerCase(Locale.ROOT);
        int need = switch (kw) {
            case "point" -> 2;
            case "segment", "rect" -> 4;
            case "triangle" -> 6;
            default -> throw new SceneFormatException(name, line,
                    "unknown shape '" + t[0] + "' (expected point, segment, rect or triangle)");
        };
        if (t.length - 1 != need)
            throw new SceneFormatException(name, line, kw + " needs " + need + " numbers, got " + (t.length - 1));
        double[] c = new double[need];
        for (int i = 0; i < need; i++) {
            try {
                c[i] = Double.parseDouble(t[i + 1]);
            } catch (NumberFormatException e) {
                throw new SceneFormatException(name, line, "'" + t[i + 1] + "' is not a number");
            }
            if (!Double.isFinite(c[i])) throw new SceneFormatException(name, line, "coordinate " + t[i + 1] + " is not finite");
        }
        return switch (kw) {
            case "point" -> new Shape2D.Point(c[0], c[1]);
            case "segment" -> new Shape2D.Segment(c[0], c[1], c[2], c[3]);
            case "rect" -> new Shape2D.Rect(c[0], c[1], c[2], c[3]);
            default -> new Shape2D.Triangle(c[0], c[1], c[2], c[3], c[4], c[5]);
        };
    }

    /**
     * Writes the shapes in the format {@link #read} accepts.
     *
     * @param scene the shapes
     * @param out receives the text
     * @throws IOException if writing fails
     */
    public static void write(Shapes2D scene, Writer out) throws IOException {
        for (Shape2D s : scene.shapes()) {
            StringBuilder b = new StringBuilder(s.keyword());
            for (double c : s.coords()) b.append(' ').append(format(c));
            out.write(b.append('\n').toString());
        }
        out.flush();
    }

    /**
     * Writes the shapes to a file in the format {@link #read} accepts.
     *
     * @param scene the shapes
     * @param file the file, replaced whole if it exists ({@link AtomicFile})
     * @throws IOException if writing fails; the file is then left as it was
     */
    public static void write(Shapes2D scene, Path file) throws IOException {
        AtomicFile.writeText(file, w -> write(scene, w));
    }

    private static String format(double c) {
        return c == Math.rint(c) && Math.abs(c) < 1e15 ? Long.toString((long) c) : Double.toString(c);
    }
}
