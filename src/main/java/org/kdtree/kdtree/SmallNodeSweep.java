package org.kdtree.kdtree;

/**
 * The exact SAH search of a small node held as references with clipped bounds
 * ({@link NodeStore#BOUNDS}), in O(n) memory and no event lists: per axis, the node's starts,
 * ends and planar positions are copied into one local array, each third sorted in place by
 * insertion (a node here has fewer than the binned search's threshold of references, about 32),
 * and swept as {@link EventSweep} sweeps a node's events: the same candidates, in the same
 * order, counted the same way, so the same plane. Its children stay in the bounds form
 * ({@link BoundsSplit}), so a small subtree is never turned into events (Shevtsov et al. 2007
 * sweep small nodes so; issue 36's small-node path).
 */
final class SmallNodeSweep {
    private SmallNodeSweep() {
    }

    /** Offers {@code best} every candidate plane of child c of level d of {@code node}'s store, held as bounds. */
    static void search(BuildNode node, SahCost sah, SahSplit best) {
        NodeStore store = node.store();
        int d = node.level(), c = node.child(), n = node.size(), k = store.k;
        double[] bounds = store.bounds(d), x = node.scratch(3 * n);
        int at = 2 * k * store.boundsMeta(d)[2 * c];
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
            sortPairs(x, n, ns);                  // the starts, each end moving with its start:
            insertionSort(x, n, n + ns);          // then the ends are nearly sorted already
            insertionSort(x, 2 * n, 2 * n + np);
            sweep(sah, best, axis, n, x, ns, np);
        }
    }

    /**
     * One axis: starts at {@code x[0, ns)}, ends at {@code x[n, n + ns)}, planars at
     * {@code x[2n, 2n + np)}, each sorted; at each distinct position, |T_L|, |T_P| and |T_R| as
     * {@link EventSweep} counts them, and the position reported as -0.0 if any of its group is.
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

    /** Sorts {@code x[from, to)} by insertion: the few values of a small node. (-0.0 and 0.0 are equal here; the sweep groups them.) */
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
