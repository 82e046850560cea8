package org.kdtree.io;

import java.io.IOException;
import java.io.Reader;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.kdtree.shape.InvalidGeometryException;
import org.kdtree.shape.TriangleMesh;

/**
 * The one reader of Wavefront OBJ files, as the benchmark spec defines them: {@code v x y z}
 * lines parsed as doubles; {@code f} lines with 1-based or negative (relative) indices in the
 * forms {@code a}, {@code a/b}, {@code a//c}, {@code a/b/c}; polygons fan-triangulated
 * (v0, vi, vi+1); triangles numbered in file order. For scenes it also reports {@code usemtl}
 * per face and the {@code mtllib} files named; every other line is ignored.
 *
 * <p>A streaming parser of our own rather than a general OBJ library: vertices and faces go
 * straight from the line into the receiver's flat arrays (a {@link Sink}), a million triangles
 * without an object per vertex, and every error names the file and line.
 */
final class ObjMeshReader {
    private ObjMeshReader() {
    }

    /** Receives an OBJ file's geometry as it is read, in file order. */
    public interface Sink {
        /**
         * One {@code v} line.
         *
         * @param x the first coordinate
         * @param y the second coordinate
         * @param z the third coordinate
         */
        void vertex(double x, double y, double z);

        /**
         * One triangle of an {@code f} line.
         *
         * @param a the first corner: 0-based index among this file's vertices
         * @param b the second corner
         * @param c the third corner
         * @param material index into {@link Materials#names()} of the {@code usemtl} in force, or -1 before any
         */
        void triangle(int a, int b, int c, int material);
    }

    /**
     * The materials an OBJ file names: what the renderer needs beyond the geometry.
     *
     * @param names       names given to {@code usemtl}, in order of first use
     * @param firstUse    the line of the first {@code usemtl} of each name (for error messages)
     * @param libraries   the {@code mtllib} files, resolved against the OBJ's folder
     */
    public record Materials(List<String> names, List<Integer> firstUse, List<Path> libraries) {
    }

    /**
     * {@return the mesh of an OBJ file}, which has at least one triangle
     *
     * @param file the OBJ file
     * @throws IOException if the file cannot be read or is malformed, is another kind of scene
     *         file (a {@code .json} render scene, a {@code .scene2d} 2-D scene: the message names
     *         the reader that fits it), or holds no triangle (no {@code f} line: no OBJ mesh)
     */
    public static TriangleMesh read(Path file) throws IOException {
        FileKind.OBJ.require(file);
        TriangleMesh m = TextLines.read(file, ObjMeshReader::mesh);
        if (m.size() == 0) throw new SceneFormatException(file.toString(), 0, NO_TRIANGLES);
        return m;
    }

    /** Why an OBJ file without faces is refused. */
    static final String NO_TRIANGLES = "no triangles (no 'f' lines): not an OBJ mesh, or an empty one";

    /**
     * {@return the mesh of OBJ text}
     *
     * @param reader the OBJ text
     * @param name used in error messages
     * @throws IOException if the text cannot be read or is malformed
     */
    public static TriangleMesh read(Reader reader, String name) throws IOException {
        return mesh(TextLines.of(reader, name));
    }

    /**
     * Streams an OBJ file's vertices and triangles into {@code sink}.
     *
     * @param file the OBJ file
     * @param sink receives the geometry
     * @return the materials the file names
     * @throws IOException if the file cannot be read or is malformed
     */
    public static Materials read(Path file, Sink sink) throws IOException {
        return TextLines.read(file, lines -> stream(lines, file.toAbsolutePath().getParent(), sink));
    }

    private static TriangleMesh mesh(TextLines in) throws IOException {
        MeshArrays arrays = new MeshArrays();
        stream(in, Path.of(""), arrays);
        try {
            return arrays.mesh();
        } catch (InvalidGeometryException e) {
            throw new SceneFormatException(in.name(), 0, e.getMessage());
        }
    }

    /** The one loop over the lines. */
    private static Materials stream(TextLines in, Path dir, Sink sink) throws IOException {
        String name = in.name();
        Map<String, Integer> materialIndex = new LinkedHashMap<>();
        List<Integer> firstUse = new ArrayList<>();
        List<Path> libraries = new ArrayList<>();
        int vertexCount = 0, current = -1;
        int[] face = new int[16];
        for (String line = in.next(); line != null; line = in.next()) {
            int lineNo = in.line();
            int hash = line.indexOf('#');
            String s = (hash >= 0 ? line.substring(0, hash) : line).strip(); // a comment may end any line
            if (s.isEmpty()) continue;
            String[] t = s.split("\\s+");
            switch (t[0]) {
                case "v" -> {
                    if (t.length < 4) throw new SceneFormatException(name, lineNo, "a vertex needs x y z, got '" + s + "'");
                    sink.vertex(number(t[1], name, lineNo), number(t[2], name, lineNo), number(t[3], name, lineNo));
                    vertexCount++;
                }
                case "f" -> {
                    int n = t.length - 1;
                    if (n < 3) throw new SceneFormatException(name, lineNo, "a face needs at least 3 vertices, got " + n);
                    if (face.length < n) face = new int[n];
                    for (int c = 0; c < n; c++) face[c] = index(t[c + 1], vertexCount, name, lineNo);
                    for (int c = 1; c + 1 < n; c++) sink.triangle(face[0], face[c], face[c + 1], current);
                }
                case "usemtl" -> {
                    if (t.length < 2) throw new SceneFormatException(name, lineNo, "usemtl needs a material name");
                    String m = s.substring(6).strip();
                    Integer i = materialIndex.get(m);
                    if (i == null) {
                        i = materialIndex.size();
                        materialIndex.put(m, i);
                        firstUse.add(lineNo);
                    }
                    current = i;
                }
                case "mtllib" -> {
                    if (t.length < 2) throw new SceneFormatException(name, lineNo, "mtllib needs a file name");
                    for (int i = 1; i < t.length; i++) libraries.add(dir.resolve(t[i]));
                }
                default -> { }
            }
        }
        return new Materials(List.copyOf(materialIndex.keySet()), List.copyOf(firstUse), List.copyOf(libraries));
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

    /** The mesh's flat arrays, grown by doubling and trimmed once at the end. */
    private static final class MeshArrays implements Sink {
        private double[] vertices = new double[3 * 1024];
        private int[] indices = new int[3 * 1024];
        private int nv, ni;

        @Override public void vertex(double x, double y, double z) {
            if (nv + 3 > vertices.length) vertices = Arrays.copyOf(vertices, 2 * vertices.length);
            vertices[nv++] = x;
            vertices[nv++] = y;
            vertices[nv++] = z;
        }

        @Override public void triangle(int a, int b, int c, int material) {
            if (ni + 3 > indices.length) indices = Arrays.copyOf(indices, 2 * indices.length);
            indices[ni++] = a;
            indices[ni++] = b;
            indices[ni++] = c;
        }

        TriangleMesh mesh() {
            return new TriangleMesh(Arrays.copyOf(vertices, nv), Arrays.copyOf(indices, ni));
        }
    }
}
