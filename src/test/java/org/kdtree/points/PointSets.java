package org.kdtree.points;

import java.util.Random;
import org.kdtree.shape.PointsKd;

/** The point sets and query points the point-query tests run on. */
final class PointSets {
    private PointSets() {
    }

    /** The kinds of data: each stresses the search differently. */
    enum Kind {
        /** Uniform in the unit cube. */
        RANDOM,
        /** Tight Gaussian clusters far apart: long empty cells, skinny voxels. */
        CLUSTERED,
        /** Seven distinct points, each repeated many times: distance ties at 0 and coincident points. */
        DUPLICATES,
        /** Integer coordinates 0..3: many equal coordinates, points in split planes, many equal distances. */
        GRID
    }

    /** The dimensions tested; 64 is the most a {@code KdTree} holds ({@link PointTree#MAX_DIMENSION}). */
    static final int[] DIMENSIONS = {2, 3, 8, 32, 64};

    static PointsKd of(Kind kind, int n, int k, long seed) {
        Random r = new Random(seed);
        double[] c = new double[n * k];
        switch (kind) {
            case RANDOM -> { for (int i = 0; i < c.length; i++) c[i] = r.nextDouble(); }
            case CLUSTERED -> {
                double[] centres = new double[5 * k];
                for (int i = 0; i < centres.length; i++) centres[i] = r.nextDouble() * 10;
                for (int i = 0; i < n; i++) {
                    int cl = r.nextInt(5);
                    for (int a = 0; a < k; a++) c[i * k + a] = centres[cl * k + a] + 0.01 * r.nextGaussian();
                }
            }
            case DUPLICATES -> {
                double[] distinct = new double[7 * k];
                for (int i = 0; i < distinct.length; i++) distinct[i] = r.nextDouble();
                for (int i = 0; i < n; i++) System.arraycopy(distinct, r.nextInt(7) * k, c, i * k, k);
            }
            case GRID -> { for (int i = 0; i < c.length; i++) c[i] = r.nextInt(4); }
        }
        return new PointsKd(k, c);
    }

    /**
     * Query points for {@code points}: copies of data points (distance 0), data points nudged,
     * points between grid positions (ties), and random points around and outside the bounds.
     */
    static double[][] queries(PointsKd points, int count, long seed) {
        Random r = new Random(seed ^ 0x5DEECE66DL);
        int k = points.dimension(), n = points.size();
        var box = points.bounds();
        double[][] q = new double[count][k];
        for (int j = 0; j < count; j++) {
            int p = r.nextInt(Math.max(1, n));
            for (int a = 0; a < k; a++) {
                double lo = n > 0 ? box.min(a) : 0, hi = n > 0 ? box.max(a) : 1, span = Math.max(hi - lo, 1e-3);
                q[j][a] = switch (j % 4) {
                    case 0 -> n > 0 ? points.coord(p, a) : 0;
                    case 1 -> n > 0 ? points.coord(p, a) + 0.01 * span * r.nextGaussian() : 0;
                    case 2 -> Math.floor(r.nextDouble() * 8 - 2) / 2;  // multiples of 1/2 around the grid
                    default -> lo - 0.3 * span + 1.6 * span * r.nextDouble();
                };
            }
        }
        return q;
    }
}
