package org.kdtree.kdtree;

import java.util.ArrayList;
import java.util.List;
import org.kdtree.shape.Scene2D;
import org.kdtree.shape.Shape2D;
import org.kdtree.shape.TriangleMesh;

/** Test scenes whose hard cases are known by construction. */
final class Scenes {
    private Scenes() {
    }

    /** A mesh from flat vertex and index lists. */
    static TriangleMesh mesh(List<double[]> v, List<int[]> f) {
        double[] vs = new double[3 * v.size()];
        for (int i = 0; i < v.size(); i++) System.arraycopy(v.get(i), 0, vs, 3 * i, 3);
        int[] is = new int[3 * f.size()];
        for (int i = 0; i < f.size(); i++) System.arraycopy(f.get(i), 0, is, 3 * i, 3);
        return new TriangleMesh(vs, is);
    }

    /**
     * The closed surface of the box [0,n]^3 * scale, each face an n x n grid of unit squares
     * split into two triangles (alternating diagonals), vertices shared: all faces and edges lie
     * in the candidate planes x, y, z = integer.
     */
    static TriangleMesh gridCube(int n, double scale) {
        List<double[]> v = new ArrayList<>();
        List<int[]> f = new ArrayList<>();
        java.util.Map<String, Integer> index = new java.util.HashMap<>();
        for (int axis = 0; axis < 3; axis++) {
            for (int side = 0; side <= 1; side++) {
                for (int i = 0; i < n; i++) {
                    for (int j = 0; j < n; j++) {
                        int[] q = new int[4];
                        int[][] uv = {{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}};
                        for (int c = 0; c < 4; c++) {
                            double[] p = new double[3];
                            p[axis] = side * n;
                            p[(axis + 1) % 3] = uv[c][0];
                            p[(axis + 2) % 3] = uv[c][1];
                            for (int a = 0; a < 3; a++) p[a] *= scale;
                            String key = p[0] + "," + p[1] + "," + p[2];
                            q[c] = index.computeIfAbsent(key, k -> { v.add(p); return v.size() - 1; });
                        }
                        if (((i + j) & 1) == 0) {
                            f.add(new int[] {q[0], q[1], q[2]});
                            f.add(new int[] {q[0], q[2], q[3]});
                        } else {
                            f.add(new int[] {q[0], q[1], q[3]});
                            f.add(new int[] {q[1], q[2], q[3]});
                        }
                    }
                }
            }
        }
        return mesh(v, f);
    }

    /** A closed UV sphere of radius r about c, with shared vertices and poles. */
    static TriangleMesh sphere(double cx, double cy, double cz, double r, int stacks, int slices) {
        List<double[]> v = new ArrayList<>();
        List<int[]> f = new ArrayList<>();
        v.add(new double[] {cx, cy, cz + r});
        for (int i = 1; i < stacks; i++) {
            double th = Math.PI * i / stacks;
            for (int j = 0; j < slices; j++) {
                double ph = 2 * Math.PI * j / slices;
                v.add(new double[] {cx + r * Math.sin(th) * Math.cos(ph), cy + r * Math.sin(th) * Math.sin(ph),
                        cz + r * Math.cos(th)});
            }
        }
        v.add(new double[] {cx, cy, cz - r});
        int south = v.size() - 1;
        for (int j = 0; j < slices; j++) {
            int j1 = (j + 1) % slices;
            f.add(new int[] {0, 1 + j, 1 + j1});
            for (int i = 1; i < stacks - 1; i++) {
                int a = 1 + (i - 1) * slices, b = 1 + i * slices;
                f.add(new int[] {a + j, b + j, b + j1});
                f.add(new int[] {a + j, b + j1, a + j1});
            }
            int last = 1 + (stacks - 2) * slices;
            f.add(new int[] {last + j, south, last + j1});
        }
        return mesh(v, f);
    }


    /** A 2-D grid of n x n unit rectangles and their outline segments, plus triangles and points. */
    static Scene2D grid2D(int n) {
        List<Shape2D> s = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) {
                if (((i + j) % 3) == 0) s.add(new Shape2D.Rect(i, j, i + 1, j + 1));
                else if (((i + j) % 3) == 1) s.add(new Shape2D.Triangle(i, j, i + 1, j, i, j + 1));
                else s.add(new Shape2D.Segment(i, j, i + 1, j + 1));
            }
            s.add(new Shape2D.Point(i + 0.5, n));
        }
        return new Scene2D(s);
    }
}
