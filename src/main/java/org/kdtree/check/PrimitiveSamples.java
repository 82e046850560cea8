package org.kdtree.check;

import java.util.ArrayList;
import java.util.List;
import org.kdtree.shape.PointsKd;
import org.kdtree.shape.Primitives;
import org.kdtree.shape.Scene2D;
import org.kdtree.shape.Shape2D;
import org.kdtree.shape.TriangleMesh;

/** Points that lie on a primitive: its vertices, points on its edges and inside it. */
final class PrimitiveSamples {
    private PrimitiveSamples() {
    }

    /** Sample points of primitive i, for the kinds of primitives this library ships. */
    static List<double[]> of(Primitives prims, int i) {
        if (prims instanceof TriangleMesh m) {
            double[][] c = new double[3][3];
            for (int corner = 0; corner < 3; corner++)
                for (int a = 0; a < 3; a++) c[corner][a] = m.corner(i, corner, a);
            return polygon(c, true);
        }
        if (prims instanceof Scene2D s) return shape(s.get(i));
        if (prims instanceof PointsKd p) {
            double[] x = new double[p.dimension()];
            for (int a = 0; a < x.length; a++) x[a] = p.coord(i, a);
            return List.of(x);
        }
        throw new IllegalArgumentException("no samples for " + prims.getClass().getSimpleName());
    }

    private static List<double[]> shape(Shape2D s) {
        double[] c = s.coords();
        if (s instanceof Shape2D.Point p) return List.of(new double[] {p.x(), p.y()});
        if (s instanceof Shape2D.Segment) return polygon(new double[][] {{c[0], c[1]}, {c[2], c[3]}}, false);
        if (s instanceof Shape2D.Rect) {
            List<double[]> out = polygon(new double[][] {{c[0], c[1]}, {c[2], c[1]}, {c[2], c[3]}}, true);
            out.addAll(polygon(new double[][] {{c[0], c[1]}, {c[2], c[3]}, {c[0], c[3]}}, true));
            return out;
        }
        return polygon(new double[][] {{c[0], c[1]}, {c[2], c[3]}, {c[4], c[5]}}, true);
    }

    /** Vertices, points along each edge and, for a filled polygon, barycentric points inside. */
    private static List<double[]> polygon(double[][] v, boolean filled) {
        List<double[]> out = new ArrayList<>();
        int n = v.length, k = v[0].length;
        for (double[] p : v) out.add(p.clone());
        double[] ts = {0.1, 0.37, 0.5, 0.81};
        for (int e = 0; e < n; e++) {
            double[] a = v[e], b = v[(e + 1) % n];
            for (double t : ts) out.add(lerp(a, b, t, k));
        }
        if (filled && n == 3) {
            double[][] bary = {{1 / 3.0, 1 / 3.0}, {0.1, 0.2}, {0.6, 0.3}, {0.2, 0.7}, {0.05, 0.05}};
            for (double[] uv : bary) {
                double[] p = new double[k];
                for (int a = 0; a < k; a++) p[a] = (1 - uv[0] - uv[1]) * v[0][a] + uv[0] * v[1][a] + uv[1] * v[2][a];
                out.add(p);
            }
        }
        return out;
    }

    private static double[] lerp(double[] a, double[] b, double t, int k) {
        double[] p = new double[k];
        for (int i = 0; i < k; i++) p[i] = a[i] + t * (b[i] - a[i]);
        return p;
    }
}
