package org.kdtree.kdtree;

import org.kdtree.geom.OutwardFloat;

/**
 * The SAH search of a small node held in floats ({@link NodeStore#FLOATS}), in O(n) memory and
 * no event lists: per axis, the node's starts, ends and planar positions are copied into one
 * local float array, each third sorted in place by insertion (a node here has fewer than the
 * binned search's threshold of references, about 32), and swept as {@link EventSweep} sweeps a
 * node's events: the same candidates, counted the same way, at the float bounds (which contain
 * the exact ones). Its children stay in the float form ({@link FloatSplit}), so a small subtree
 * is never turned into events (Shevtsov et al. 2007 sweep small nodes so; issue 36's small-node path).
 */
final class SmallNodeSweep {
    private SmallNodeSweep() {
    }

    /** Offers {@code best} every candidate plane of child c of level d of {@code node}'s store, held in floats. */
    static void search(BuildNode node, SahCost sah, SahSplit best) {
        NodeStore store = node.store();
        int d = node.level(), c = node.child(), n = node.size(), k = store.k;
        float[][] f = store.floats(d);
        float[] x = store.floatScratch(3 * n);
        int at = store.boundsMeta(d)[2 * c];
        for (int axis = 0; axis < k; axis++) {
            float[] mins = f[axis], maxs = f[k + axis];
            int ns = 0, np = 0;
            for (int j = at; j < at + n; j++) {
                float lo = mins[j], hi = maxs[j];
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
            double[] v = store.voxel(d);
            float first = Math.nextUp(OutwardFloat.down(v[2 * k * c + axis]));    // a plane p needs nextDown(p) > the voxel's minimum
            float last = Math.nextDown(OutwardFloat.up(v[2 * k * c + k + axis]));  // and nextUp(p) < its maximum
            sweep(sah, best, axis, n, x, ns, np, first, last);
        }
    }

    /**
     * One axis: starts at {@code x[0, ns)}, ends at {@code x[n, n + ns)}, planars at
     * {@code x[2n, 2n + np)}, each sorted; at each distinct position, |T_L|, |T_P| and |T_R| as
     * {@link EventSweep} counts them, and the position reported as -0.0 if any of its group is.
     * No plane within a float's ulp of the voxel's faces: there lie the bounds a clip left at a
     * face, rounded to nearest, and a plane there would cut nothing off.
     */
    private static void sweep(SahCost sah, SahSplit best, int axis, int n, float[] x, int ns, int np, float first, float last) {
        int is = 0, ie = n, ip = 2 * n, endS = ns, endE = n + ns, endP = 2 * n + np;
        int nl = 0, nr = n;
        while (is < endS || ie < endE || ip < endP) {
            float p = Float.POSITIVE_INFINITY;
            if (is < endS) p = x[is];
            if (ie < endE) p = Math.min(p, x[ie]);
            if (ip < endP) p = Math.min(p, x[ip]);
            float at = p;
            int ends = 0, planar = 0, starts = 0;
            for (; ie < endE && x[ie] == at; ie++, ends++) p = Math.min(p, x[ie]);
            for (; ip < endP && x[ip] == at; ip++, planar++) p = Math.min(p, x[ip]);
            for (; is < endS && x[is] == at; is++, starts++) p = Math.min(p, x[is]);
            nr -= planar + ends;
            if (p > first && p < last) best.offer(sah, axis, p, nl, planar, nr);
            nl += starts + planar;
        }
    }

    /**
     * Sorts the starts {@code x[0, ns)} by insertion, moving each reference's end
     * ({@code x[n + j]}) with its start: a triangle's end lies a little after its start, so the
     * ends come out nearly sorted, and their own sort is almost linear.
     */
    private static void sortPairs(float[] x, int n, int ns) {
        for (int i = 1; i < ns; i++) {
            float v = x[i], e = x[n + i];
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
    private static void insertionSort(float[] x, int from, int to) {
        for (int i = from + 1; i < to; i++) {
            float v = x[i];
            int j = i - 1;
            while (j >= from && x[j] > v) {
                x[j + 1] = x[j];
                j--;
            }
            x[j + 1] = v;
        }
    }
}
