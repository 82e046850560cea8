package org.kdtree.io;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * An OBJ mesh with the material of each triangle: geometry read exactly as {@link ObjMeshReader}
 * reads it (same triangles, same order), plus {@code usemtl} per face and the {@code mtllib}
 * files named. Triangles before any {@code usemtl} have material -1 (the scene's default).
 *
 * @param vertices      x, y, z per vertex
 * @param indices       three vertex indices per triangle
 * @param materialOf    per triangle, an index into {@code materialNames}, or -1
 * @param materialNames names given to {@code usemtl}, in order of first use
 * @param usemtlLines   the line of the first {@code usemtl} of each name (for error messages)
 * @param libraries     the {@code mtllib} files, resolved against the OBJ's folder
 * @param file          the OBJ file
 */
public record ObjMaterialMesh(double[] vertices, int[] indices, int[] materialOf, List<String> materialNames,
                              List<Integer> usemtlLines, List<Path> libraries, Path file) {

    /**
     * {@return the mesh and materials of an OBJ file}; errors name the file and line.
     *
     * @param file the OBJ file
     * @throws IOException if the file cannot be read or is malformed
     */
    public static ObjMaterialMesh read(Path file) throws IOException {
        if (!Files.isRegularFile(file)) throw new SceneFormatException(file.toString(), 0, "no such file");
        String name = file.toString();
        double[] v = new double[3 * 1024];
        int nv = 0;
        int[] tris = new int[3 * 1024], mats = new int[1024];
        int nt = 0;
        Map<String, Integer> materialIndex = new LinkedHashMap<>();
        List<Integer> firstUse = new ArrayList<>();
        List<Path> libs = new ArrayList<>();
        int current = -1;
        int[] face = new int[16];
        try (TextLines in = TextLines.open(file)) {
            for (String line = in.next(); line != null; line = in.next()) {
                int lineNo = in.line();
                String s = line.strip();
                String[] t = s.split("\\s+");
                switch (t[0]) {
                    case "v" -> {
                        if (t.length < 4) throw new SceneFormatException(name, lineNo, "a vertex needs x y z, got '" + s + "'");
                        if (3 * nv + 3 > v.length) v = Arrays.copyOf(v, 2 * v.length);
                        for (int a = 1; a <= 3; a++) v[3 * nv + a - 1] = ObjMeshReader.number(t[a], name, lineNo);
                        nv++;
                    }
                    case "f" -> {
                        int n = t.length - 1;
                        if (n < 3) throw new SceneFormatException(name, lineNo, "a face needs at least 3 vertices, got " + n);
                        if (face.length < n) face = new int[n];
                        for (int c = 0; c < n; c++) face[c] = ObjMeshReader.index(t[c + 1], nv, name, lineNo);
                        for (int c = 1; c + 1 < n; c++) {
                            if (3 * nt + 3 > tris.length) {
                                tris = Arrays.copyOf(tris, 2 * tris.length);
                                mats = Arrays.copyOf(mats, 2 * mats.length);
                            }
                            tris[3 * nt] = face[0];
                            tris[3 * nt + 1] = face[c];
                            tris[3 * nt + 2] = face[c + 1];
                            mats[nt++] = current;
                        }
                    }
                    case "usemtl" -> {
                        if (t.length < 2) throw new SceneFormatException(name, lineNo, "usemtl needs a material name");
                        String m = s.substring(6).strip();
                        Integer idx = materialIndex.get(m);
                        if (idx == null) {
                            idx = materialIndex.size();
                            materialIndex.put(m, idx);
                            firstUse.add(lineNo);
                        }
                        current = idx;
                    }
                    case "mtllib" -> {
                        if (t.length < 2) throw new SceneFormatException(name, lineNo, "mtllib needs a file name");
                        Path dir = file.toAbsolutePath().getParent();
                        for (int i = 1; i < t.length; i++) libs.add(dir.resolve(t[i]));
                    }
                    default -> { }
                }
            }
        }
        return new ObjMaterialMesh(Arrays.copyOf(v, 3 * nv), Arrays.copyOf(tris, 3 * nt), Arrays.copyOf(mats, nt),
                List.copyOf(materialIndex.keySet()), List.copyOf(firstUse), List.copyOf(libs), file);
    }

    /** {@return the number of triangles} */
    public int triangleCount() { return materialOf.length; }
}
