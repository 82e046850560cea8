package org.kdtree.kdtree;

import java.util.Arrays;

/**
 * Sort-then-sweep (Wald and Havran, section 4.2): per axis, sort the start, end and planar
 * events of the node's primitives, then sweep the plane across them keeping |T_L|, |T_P| and
 * |T_R| up to date. O(|T| log |T|) per node, so O(N log^2 N) for the whole build.
 *
 * <p>The three event kinds are sorted as separate primitive arrays and merged during the sweep,
 * which keeps the order "ends, then planars, then starts" at equal positions.
 */
final class SortedPlaneSearch implements PlaneSearch {
    @Override public void search(BuildNode node, SahCost sah, SahSplit best) {
        int n = node.size();
        double[] starts = new double[n], ends = new double[n], planars = new double[n];
        for (int axis = 0; axis < node.dimension(); axis++) {
            int ns = 0, np = 0;
            for (int j = 0; j < n; j++) {
                double lo = node.clippedMin(j, axis), hi = node.clippedMax(j, axis);
                if (lo == hi) planars[np++] = lo;
                else {
                    starts[ns] = lo;
                    ends[ns++] = hi;
                }
            }
            Arrays.sort(starts, 0, ns);
            Arrays.sort(ends, 0, ns);
            Arrays.sort(planars, 0, np);
            sweep(sah, best, axis, n, starts, ends, ns, planars, np);
        }
    }

    /** The sweep over one axis's sorted starts, ends and planar positions ({@link EventSweep} counts a node's event lists the same way). */
    static void sweep(SahCost sah, SahSplit best, int axis, int n,
                      double[] starts, double[] ends, int ns, double[] planars, int np) {
        int is = 0, ie = 0, ip = 0;
        int nl = 0, nr = n;
        while (is < ns || ie < ns || ip < np) {
            double x = Double.POSITIVE_INFINITY;
            if (is < ns) x = starts[is];
            if (ie < ns) x = Math.min(x, ends[ie]);
            if (ip < np) x = Math.min(x, planars[ip]);
            int pEnd = 0, pPlanar = 0, pStart = 0;
            while (ie < ns && ends[ie] == x) { ie++; pEnd++; }
            while (ip < np && planars[ip] == x) { ip++; pPlanar++; }
            while (is < ns && starts[is] == x) { is++; pStart++; }
            nr -= pPlanar + pEnd;
            best.offer(sah, axis, x, nl, pPlanar, nr);
            nl += pStart + pPlanar;
        }
    }
}
