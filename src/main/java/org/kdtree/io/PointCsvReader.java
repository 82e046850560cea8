package org.kdtree.io;

import java.io.IOException;
import java.io.Reader;
import java.nio.file.Path;
import java.util.Arrays;
import org.kdtree.geom.Tolerance;
import org.kdtree.shape.InvalidGeometryException;
import org.kdtree.shape.PointsKd;

/**
 * Reads k-D points from a CSV file: one point per line, its coordinates as decimal numbers
 * separated by commas ({@code 0.5,1,-2e3}; spaces around a number are allowed). Every point has
 * the dimension of the first; blank lines and lines starting with {@code #} are skipped. Any
 * other line that is not such a point (a wrong count, a field that is not a number, a
 * non-finite one) is an error naming the file and the line. Points are numbered from 0 in file
 * order. See docs/points.md.
 */
final class PointCsvReader {
    private PointCsvReader() {
    }

    /**
     * {@return the points of a point file}; a file without any point is an error.
     *
     * @param file the CSV file
     * @throws IOException if the file cannot be read or is malformed
     */
    public static PointsKd read(Path file) throws IOException {
        return TextLines.read(file, PointCsvReader::read);
    }

    /**
     * {@return the points of point CSV text}
     *
     * @param reader the CSV text
     * @param name used in error messages
     * @throws IOException if the text cannot be read or is malformed
     */
    public static PointsKd read(Reader reader, String name) throws IOException {
        return read(TextLines.of(reader, name));
    }

    private static PointsKd read(TextLines in) throws IOException {
        double[] coords = new double[1024];
        int n = 0, k = 0, firstLine = 0;
        for (String line = in.next(); line != null; line = in.next()) {
            String s = line.strip();
            if (s.isEmpty() || s.startsWith("#")) continue;
            String[] fields = s.split(",", -1);
            if (k == 0) {
                k = fields.length;
                firstLine = in.line();
            } else if (fields.length != k) {
                throw new SceneFormatException(in.name(), in.line(), "a point needs " + k + " coordinates, as on line "
                        + firstLine + ", got " + fields.length);
            }
            if (n + k > coords.length) coords = Arrays.copyOf(coords, Math.max(2 * coords.length, n + k));
            for (String f : fields) coords[n++] = coordinate(f.strip(), in);
        }
        if (k == 0) throw new SceneFormatException(in.name(), 0, "no points (one point per line, coordinates separated by commas)");
        try {
            return new PointsKd(k, Arrays.copyOf(coords, n));
        } catch (InvalidGeometryException e) {   // the points as a whole, such as an extent too small
            throw new SceneFormatException(in.name(), 0, e.getMessage());
        }
    }

    private static double coordinate(String field, TextLines in) throws SceneFormatException {
        if (field.isEmpty()) throw new SceneFormatException(in.name(), in.line(), "an empty field where a coordinate belongs");
        double x = ObjMeshReader.number(field, in.name(), in.line());
        if (Math.abs(x) > Tolerance.MAX_COORDINATE)
            throw new SceneFormatException(in.name(), in.line(), "the coordinate " + field
                    + " is outside the supported range -1e100 .. 1e100 (squared distances would overflow); scale the points down");
        return x;
    }
}
