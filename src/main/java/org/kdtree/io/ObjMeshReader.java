package org.kdtree.io;

import java.io.IOException;
import java.io.InputStreamReader;
import java.io.Reader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import org.kdtree.shape.InvalidGeometryException;
import org.kdtree.shape.TriangleMesh;

/**
 * Reads the geometry of a Wavefront OBJ file into a {@link TriangleMesh}, as the benchmark
 * spec defines it: {@code v x y z} lines parsed as doubles; {@code f} lines with 1-based or
 * negative (relative) indices in the forms {@code a}, {@code a/b}, {@code a//c}, {@code a/b/c};
 * polygons fan-triangulated (v0, vi, vi+1); triangles numbered in file order; every other
 * line ignored. Materials are the renderer's business (see the scene reader).
 *
 * <p>A streaming parser of our own rather than a general OBJ library: it reads a million
 * triangles straight into flat arrays, and every error names the file and line.
 */
public final class ObjMeshReader {
    private ObjMeshReader() {
    }

    /**
     * {@return the mesh of an OBJ file}
     *
     * @param file the OBJ file
     * @throws IOException if the file cannot be read or is malformed
     */
    public static TriangleMesh read(Path file) throws IOException {
        try (TextLines lines = TextLines.open(file)) {
            return read(lines);
        }
    }

    /**
     * {@return the mesh of OBJ text}
     *
     * @param reader the OBJ text
     * @param name used in error messages
     * @throws IOException if the text cannot be read or is malformed
     */
    public static TriangleMesh read(Reader reader, String name) throws IOException {
        return read(TextLines.of(reader, name));
    }

    private static TriangleMesh read(TextLines in) throws IOException {
        String name = in.name();
        DoubleList v = new DoubleList();
        IntList tris = new IntList();
        int[] face = new int[16];
        for (String line = in.next(); line != null; line = in.next()) {
            int lineNo = in.line();
            String s = line.strip();
            if (s.startsWith("v ") || s.startsWith("v\t")) {
                String[] t = s.split("\\s+");
                if (t.length < 4) throw new SceneFormatException(name, lineNo, "a vertex needs x y z, got '" + s + "'");
                for (int a = 1; a <= 3; a++) v.add(number(t[a], name, lineNo));
            } else if (s.startsWith("f ") || s.startsWith("f\t")) {
                String[] t = s.split("\\s+");
                int n = t.length - 1;
                if (n < 3) throw new SceneFormatException(name, lineNo, "a face needs at least 3 vertices, got " + n);
                if (face.length < n) face = new int[n];
                int vertexCount = v.size() / 3;
                for (int c = 0; c < n; c++) face[c] = index(t[c + 1], vertexCount, name, lineNo);
                for (int c = 1; c + 1 < n; c++) tris.add(face[0], face[c], face[c + 1]);
            }
        }
        try {
            return new TriangleMesh(v.toArray(), tris.toArray());
        } catch (InvalidGeometryException e) {
            throw new SceneFormatException(name, 0, e.getMessage());
        }
    }

    /**
     * {@return the mesh of an OBJ file on the class path} (bundled scenes).
     *
     * @param resource the resource's name
     * @throws IOException if there is no such resource or it is malformed
     */
    public static TriangleMesh readResource(String resource) throws IOException {
        var stream = ObjMeshReader.class.getResourceAsStream(resource);
        if (stream == null) throw new SceneFormatException(resource, 0, "no such resource");
        try (Reader r = new InputStreamReader(stream, StandardCharsets.UTF_8)) {
            return read(r, resource);
        }
    }

    /** A finite coordinate, or an error naming the file and line. */
    static double number(String token, String name, int line) throws SceneFormatException {
        double d;
        try {
            d = Double.parseDouble(token);
        } catch (NumberFormatException e) {
            throw new SceneFormatException(name, line, "'" + token + "' is not a number");
        }
        if (!Double.isFinite(d)) throw new SceneFormatException(name, line, "coordinate " + token + " is not finite");
        return d;
    }

    /** A face corner "a", "a/b", "a//c" or "a/b/c" to a 0-based vertex index. */
    static int index(String token, int vertexCount, String name, int line) throws SceneFormatException {
        int slash = token.indexOf('/');
        String head = slash < 0 ? token : token.substring(0, slash);
        int i;
        try {
            i = Integer.parseInt(head);
        } catch (NumberFormatException e) {
            throw new SceneFormatException(name, line, "'" + token + "' is not a vertex index");
        }
        int zeroBased = i > 0 ? i - 1 : vertexCount + i;
        if (i == 0 || zeroBased < 0 || zeroBased >= vertexCount)
            throw new SceneFormatException(name, line, "vertex index " + i + " out of range (" + vertexCount
                    + " vertices defined so far)");
        return zeroBased;
    }

    private static final class DoubleList {
        private double[] a = new double[1024];
        private int n;

        void add(double x) {
            if (n == a.length) a = java.util.Arrays.copyOf(a, n * 2);
            a[n++] = x;
        }

        int size() { return n; }
        double[] toArray() { return java.util.Arrays.copyOf(a, n); }
    }

    private static final class IntList {
        private int[] a = new int[1024];
        private int n;

        void add(int x, int y, int z) {
            if (n + 3 > a.length) a = java.util.Arrays.copyOf(a, a.length * 2);
            a[n++] = x;
            a[n++] = y;
            a[n++] = z;
        }

        int[] toArray() { return java.util.Arrays.copyOf(a, n); }
    }
}
