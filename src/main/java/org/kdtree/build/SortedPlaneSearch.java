package org.kdtree.build;

import java.util.Arrays;

/**
 * Sort-then-sweep (Wald and Havran, section 4.2): per axis, sort the start, end and planar
 * events of the node's primitives, then sweep the plane across them keeping |T_L|, |T_P| and
 * |T_R| up to date. O(|T| log |T|) per node, so O(N log^2 N) for the whole build.
 *
 * <p>The three event kinds are sorted as separate primitive arrays and merged during the sweep,
 * which keeps the order "ends, then planars, then starts" at equal positions.
 */
public final class SortedPlaneSearch implements PlaneSearch {
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
            sweep(sah, best, axis, n, starts, 0, ends, 0, ns, planars, 0, np);
        }
    }

    /**
     * The sweep over one axis's sorted events: {@code ns} starts from {@code starts[s0]}, as many
     * ends from {@code ends[e0]}, {@code np} planar positions from {@code planars[p0]}; shared
     * with {@link BoundsSweep}, which keeps the three in one scratch array.
     */
    static void sweep(SahCost sah, SahSplit best, int axis, int n, double[] starts, int s0, double[] ends, int e0, int ns,
                      double[] planars, int p0, int np) {
        int is = s0, ie = e0, ip = p0, sEnd = s0 + ns, eEnd = e0 + ns, pEnd = p0 + np;
        int nl = 0, nr = n;
        while (is < sEnd || ie < eEnd || ip < pEnd) {
            double x = Double.POSITIVE_INFINITY;
            if (is < sEnd) x = starts[is];
            if (ie < eEnd) x = Math.min(x, ends[ie]);
            if (ip < pEnd) x = Math.min(x, planars[ip]);
            int ending = 0, planar = 0, starting = 0;
            while (ie < eEnd && ends[ie] == x) { ie++; ending++; }
            while (ip < pEnd && planars[ip] == x) { ip++; planar++; }
            while (is < sEnd && starts[is] == x) { is++; starting++; }
            nr -= planar + ending;
            best.offer(sah, axis, x, nl, planar, nr);
            nl += starting + planar;
        }
    }
}
