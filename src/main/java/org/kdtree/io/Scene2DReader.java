package org.kdtree.io;

import java.io.IOException;
import java.io.Reader;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.kdtree.shape.Scene2D;
import org.kdtree.shape.Shape2D;

/**
 * The 2-D scene format of the workbench: one shape per line, {@code #} starts a comment.
 * <pre>
 * point    x y
 * segment  x0 y0 x1 y1
 * rect     x0 y0 x1 y1          (two opposite corners)
 * triangle ax ay bx by cx cy
 * </pre>
 * Files end in {@code .scene2d} ({@link Scene2DWriter} writes them). See docs/scene-format.md.
 */
final class Scene2DReader {
    private Scene2DReader() {
    }

    /**
     * {@return the shapes of a {@code .scene2d} file}
     *
     * @param file the file
     * @throws IOException if the file cannot be read or is malformed
     */
    public static Scene2D read(Path file) throws IOException {
        FileKind.SCENE2D.require(file);
        return TextLines.read(file, Scene2DReader::read);
    }

    /**
     * {@return the shapes of 2-D scene text}
     *
     * @param reader the text
     * @param name used in error messages
     * @throws IOException if the text cannot be read or is malformed
     */
    public static Scene2D read(Reader reader, String name) throws IOException {
        return read(TextLines.of(reader, name));
    }

    private static Scene2D read(TextLines in) throws IOException {
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
        return new Scene2D(shapes);
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

}
