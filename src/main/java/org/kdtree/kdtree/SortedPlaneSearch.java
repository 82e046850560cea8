package org.kdtree.kdtree;

import java.util.Arrays;

/**
 * Sort-then-sweep (Wald and Havran, section 4.2): per axis, sort the start, end and planar
 * positions of the node's references (their clipped bounds), then sweep the plane across them
 * keeping |T_L|, |T_P| and |T_R| up to date. O(|T| log |T|) per node, so O(N log^2 N) for the
 * whole build (the SORTED algorithm).
 *
 * <p>It is also the exact search of the binned search's small nodes, held as bounds, so that a
 * small subtree is never turned into events (Shevtsov et al. 2007 sweep small nodes so). There
 * the few values are sorted by insertion, each end moving with its start, which leaves the ends
 * nearly sorted: cheaper than {@link Arrays#sort} below {@link #INSERTION_BELOW} references. Either
 * sort gives the same sorted positions, so the same plane.
 *
 * <p>Per axis the positions sit in one scratch array: starts at {@code [0, ns)}, ends at
 * {@code [n, n + ns)}, planars at {@code [2n, 2n + np)}; the sweep counts them as
 * {@link EventSweep} counts a node's events: the same candidates, in the same order, the same plane.
 */
final class SortedPlaneSearch implements PlaneSearch {
    /** The one instance: the search keeps nothing between nodes. */
    static final SortedPlaneSearch INSTANCE = new SortedPlaneSearch();

    /** Nodes smaller than this are sorted by insertion. */
    private static final int INSERTION_BELOW = 64;

    @Override public void search(BuildNode node, SahCost sah, SahSplit best) {
        int n = node.size(), k = node.dimension();
        double[] bounds = node.boundsArray(), x = node.scratch(3 * n);
        int at = 2 * k * node.boundsFrom();
        for (int axis = 0; axis < k; axis++) {
            int ns = 0, np = 0;
            for (int j = 0, o = at + axis; j < n; j++, o += 2 * k) {
                double lo = bounds[o], hi = bounds[o + k];
                if (lo == hi) {
                    x[2 * n + np++] = lo;
                } else {
                    x[ns] = lo;
                    x[n + ns++] = hi;
                }
            }
            if (n < INSERTION_BELOW) {
                sortPairs(x, n, ns);
                insertionSort(x, n, n + ns);
                insertionSort(x, 2 * n, 2 * n + np);
            } else {
                Arrays.sort(x, 0, ns);
                Arrays.sort(x, n, n + ns);
                Arrays.sort(x, 2 * n, 2 * n + np);
            }
            sweep(sah, best, axis, n, x, ns, np);
        }
    }

    /**
     * One axis, its starts, ends and planars each sorted: at each distinct position, |T_L|, |T_P|
     * and |T_R| as {@link EventSweep} counts them, and the position reported as -0.0 if any of its
     * group is (whichever order the sort left -0.0 and 0.0 in).
     */
    private static void sweep(SahCost sah, SahSplit best, int axis, int n, double[] x, int ns, int np) {
        int is = 0, ie = n, ip = 2 * n, endS = ns, endE = n + ns, endP = 2 * n + np;
        int nl = 0, nr = n;
        while (is < endS || ie < endE || ip < endP) {
            double p = Double.POSITIVE_INFINITY;
            if (is < endS) p = x[is];
            if (ie < endE) p = Math.min(p, x[ie]);
            if (ip < endP) p = Math.min(p, x[ip]);
            double at = p;
            int ends = 0, planar = 0, starts = 0;
            for (; ie < endE && x[ie] == at; ie++, ends++) p = Math.min(p, x[ie]);
            for (; ip < endP && x[ip] == at; ip++, planar++) p = Math.min(p, x[ip]);
            for (; is < endS && x[is] == at; is++, starts++) p = Math.min(p, x[is]);
            nr -= planar + ends;
            best.offer(sah, axis, p, nl, planar, nr);
            nl += starts + planar;
        }
    }

    /**
     * Sorts the starts {@code x[0, ns)} by insertion, moving each reference's end
     * ({@code x[n + j]}) with its start: a triangle's end lies a little after its start, so the
     * ends come out nearly sorted, and their own sort is almost linear.
     */
    private static void sortPairs(double[] x, int n, int ns) {
        for (int i = 1; i < ns; i++) {
            double v = x[i], e = x[n + i];
            int j = i - 1;
            while (j >= 0 && x[j] > v) {
                x[j + 1] = x[j];
                x[n + j + 1] = x[n + j];
                j--;
            }
            x[j + 1] = v;
            x[n + j + 1] = e;
        }
    }

    /** Sorts {@code x[from, to)} by insertion. (-0.0 and 0.0 are equal here; the sweep groups them.) */
    private static void insertionSort(double[] x, int from, int to) {
        for (int i = from + 1; i < to; i++) {
            double v = x[i];
            int j = i - 1;
            while (j >= from && x[j] > v) {
                x[j + 1] = x[j];
                j--;
            }
            x[j + 1] = v;
        }
    }
}
