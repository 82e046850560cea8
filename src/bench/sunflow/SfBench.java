package org.sunflow.core;

import java.nio.file.*;
import java.util.*;
import org.sunflow.core.accel.KDTree;
import org.sunflow.core.primitive.TriangleMesh;
import org.sunflow.core.ParameterList.InterpolationType;
import org.sunflow.system.UI;

/** The benchmark spec (docs/benchmark-spec.md) on Sunflow's KDTree: build median of 5 after 2 warm-ups, ray sets P and R. */
public class SfBench {
    public static void main(String[] a) throws Exception {
        UI.verbosity(0);
        List<double[]> vs = new ArrayList<>(); List<int[]> fs = new ArrayList<>();
        for (String line : Files.readAllLines(Path.of(a[0]))) {
            String[] t = line.trim().split("\\s+");
            if (t[0].equals("v")) vs.add(new double[]{Double.parseDouble(t[1]), Double.parseDouble(t[2]), Double.parseDouble(t[3])});
            else if (t[0].equals("f")) {
                int[] idx = new int[t.length - 1];
                for (int i = 1; i < t.length; i++) { int k = Integer.parseInt(t[i].split("/")[0]); idx[i-1] = k < 0 ? vs.size() + k : k - 1; }
                for (int i = 1; i + 1 < idx.length; i++) fs.add(new int[]{idx[0], idx[i], idx[i+1]});
            }
        }
        float[] pts = new float[vs.size() * 3]; double[] mn = {1e300,1e300,1e300}, mx = {-1e300,-1e300,-1e300};
        for (int i = 0; i < vs.size(); i++) for (int k = 0; k < 3; k++) { double x = vs.get(i)[k]; pts[3*i+k] = (float) x; mn[k] = Math.min(mn[k], x); mx[k] = Math.max(mx[k], x); }
        int[] tris = new int[fs.size() * 3];
        for (int i = 0; i < fs.size(); i++) System.arraycopy(fs.get(i), 0, tris, 3*i, 3);
        ParameterList pl = new ParameterList();
        pl.addIntegerArray("triangles", tris);
        pl.addPoints("points", InterpolationType.VERTEX, pts);
        TriangleMesh mesh = new TriangleMesh();
        if (!mesh.update(pl, null)) throw new IllegalStateException("mesh");
        double[] bt = new double[7]; KDTree tree = null;
        for (int r = 0; r < 7; r++) { tree = new KDTree(); long t0 = System.nanoTime(); tree.build(mesh); bt[r] = (System.nanoTime() - t0) / 1e6; }
        double buildMs = median(Arrays.copyOfRange(bt, 2, 7));
        // P rays
        double[] c = new double[3], ext = new double[3]; double d2 = 0;
        for (int k = 0; k < 3; k++) { c[k] = (mn[k] + mx[k]) / 2; ext[k] = mx[k] - mn[k]; d2 += ext[k] * ext[k]; }
        double d = Math.sqrt(d2); double[] w = {1, 0.5, 2}; double wl = Math.sqrt(1 + 0.25 + 4);
        double[] eye = new double[3]; for (int k = 0; k < 3; k++) eye[k] = c[k] + 1.5 * d * w[k] / wl;
        double[] fw = norm(new double[]{c[0]-eye[0], c[1]-eye[1], c[2]-eye[2]});
        double[] rt = norm(cross(fw, new double[]{0,1,0})); double[] up = cross(rt, fw);
        double s = Math.tan(Math.toRadians(20)); int W = 1024, n = W * W;
        float[] P = new float[6 * n];
        for (int j = 0; j < W; j++) for (int i = 0; i < W; i++) {
            double x = (2 * (i + 0.5) / W - 1) * s, y = (1 - 2 * (j + 0.5) / W) * s;
            double[] dir = norm(new double[]{fw[0]+x*rt[0]+y*up[0], fw[1]+x*rt[1]+y*up[1], fw[2]+x*rt[2]+y*up[2]});
            int q = 6 * (j * W + i); for (int k = 0; k < 3; k++) { P[q+k] = (float) eye[k]; P[q+3+k] = (float) dir[k]; }
        }
        int m = 1000000; float[] R = new float[6 * m]; long[] st = {42};
        for (int i = 0; i < m; i++) {
            double ux = u(st), uy = u(st), uz = u(st), uu = u(st), vv = u(st);
            double zc = 1 - 2 * uu, phi = 2 * Math.PI * vv, r = Math.sqrt(Math.max(0, 1 - zc * zc));
            double[] o = {mn[0] + ux * ext[0], mn[1] + uy * ext[1], mn[2] + uz * ext[2]};
            double[] dd = {r * Math.cos(phi), r * Math.sin(phi), zc};
            for (int k = 0; k < 3; k++) { R[6*i+k] = (float) o[k]; R[6*i+3+k] = (float) dd[k]; }
        }
        String p = trace(tree, P), rr = trace(tree, R);
        System.out.printf(Locale.ROOT, "sunflow %s %d %.1f - - - %s %s%n", Path.of(a[0]).getFileName(), fs.size(), buildMs, p, rr);
    }
    static String trace(KDTree tree, float[] rays) {
        int n = rays.length / 6; double[] ts = new double[7]; long hits = 0; double tsum = 0;
        IntersectionState state = new IntersectionState(); state.current = new Instance();
        for (int r = 0; r < 7; r++) {
            hits = 0; tsum = 0; long t0 = System.nanoTime();
            for (int i = 0; i < n; i++) {
                int q = 6 * i; Ray ray = new Ray(rays[q], rays[q+1], rays[q+2], rays[q+3], rays[q+4], rays[q+5]);
                state.instance = null; tree.intersect(ray, state);
                if (state.hit()) { hits++; tsum += ray.getMax(); }
            }
            ts[r] = (System.nanoTime() - t0) / 1e9;
        }
        return String.format(Locale.ROOT, "%d %.6f %.3f", hits, tsum, n / median(Arrays.copyOfRange(ts, 2, 7)) / 1e6);
    }
    static double u(long[] st) { st[0] += 0x9E3779B97F4A7C15L; long z = st[0]; z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L; z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL; z = z ^ (z >>> 31); return (z >>> 11) * 0x1.0p-53; }
    static double median(double[] x) { x = x.clone(); Arrays.sort(x); return x[x.length / 2]; }
    static double[] norm(double[] v) { double l = Math.sqrt(v[0]*v[0]+v[1]*v[1]+v[2]*v[2]); return new double[]{v[0]/l, v[1]/l, v[2]/l}; }
    static double[] cross(double[] a, double[] b) { return new double[]{a[1]*b[2]-a[2]*b[1], a[2]*b[0]-a[0]*b[2], a[0]*b[1]-a[1]*b[0]}; }
}
