package org.kdtree.points;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import org.kdtree.shape.PointsKd;

/** The oracle: every point's distance computed, all points sorted by (accumulated distance, index). */
final class BruteForcePoints {
    private BruteForcePoints() {
    }

    record Neighbour(int index, double distance) {
    }

    /** The accumulated distance (sum of |d|^p axis by axis from axis 0, or the max for p = infinity). */
    static double accumulated(PointsKd pts, int i, double[] q, double p) {
        double acc = 0;
        for (int a = 0; a < q.length; a++) {
            double d = q[a] - pts.coord(i, a);
            if (p == 2) acc += d * d;
            else if (p == 1) acc += Math.abs(d);
            else if (p == Double.POSITIVE_INFINITY) acc = Math.max(acc, Math.abs(d));
            else acc += Math.pow(Math.abs(d), p);
        }
        return acc;
    }

    static double root(double acc, double p) {
        return p == 2 ? Math.sqrt(acc) : p == 1 || p == Double.POSITIVE_INFINITY ? acc : Math.pow(acc, 1 / p);
    }

    /** All points at distance <= maxDistance, sorted by accumulated distance then index. */
    static List<Neighbour> sorted(PointsKd pts, double[] q, double p, double maxDistance) {
        record Acc(int index, double acc) {
        }
        List<Acc> all = new ArrayList<>();
        for (int i = 0; i < pts.size(); i++) all.add(new Acc(i, accumulated(pts, i, q, p)));
        all.sort(Comparator.comparingDouble(Acc::acc).thenComparingInt(Acc::index));
        List<Neighbour> out = new ArrayList<>();
        for (Acc a : all) {
            double d = root(a.acc(), p);
            if (d <= maxDistance) out.add(new Neighbour(a.index(), d));
        }
        return out;
    }

    /** The k nearest within maxDistance. */
    static List<Neighbour> nearest(PointsKd pts, double[] q, int k, double p, double maxDistance) {
        List<Neighbour> s = sorted(pts, q, p, maxDistance);
        return s.subList(0, Math.min(k, s.size()));
    }

    /** Indices of the points inside the closed box, ascending. */
    static List<Integer> inside(PointsKd pts, double[] min, double[] max) {
        List<Integer> out = new ArrayList<>();
        outer:
        for (int i = 0; i < pts.size(); i++) {
            for (int a = 0; a < min.length; a++)
                if (pts.coord(i, a) < min[a] || pts.coord(i, a) > max[a]) continue outer;
            out.add(i);
        }
        return out;
    }

    /** A query's result as neighbours, for comparison with the oracle's. */
    static List<Neighbour> of(int n, int[] indices, double[] distances) {
        List<Neighbour> out = new ArrayList<>();
        for (int i = 0; i < n; i++) out.add(new Neighbour(indices[i], distances[i]));
        return out;
    }
}
