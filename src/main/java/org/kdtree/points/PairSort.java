package org.kdtree.points;

/**
 * In-place heap sorts for query results, so that sorting allocates nothing: pairs (accumulated
 * distance, point index) by distance then index, and plain point indices.
 */
final class PairSort {
    private PairSort() {
    }

    /** Sorts the first {@code n} pairs {@code (key[i], index[i])} ascending by key, ties by index. */
    static void sort(double[] key, int[] index, int n) {
        for (int i = n / 2 - 1; i >= 0; i--) siftDown(key, index, i, n);
        for (int end = n - 1; end > 0; end--) {
            swap(key, index, 0, end);
            siftDown(key, index, 0, end);
        }
    }

    /** Whether pair i comes after pair j: larger distance, or the same distance and a larger index. */
    static boolean after(double ki, int ii, double kj, int ij) {
        return ki > kj || (ki == kj && ii > ij);
    }

    /** Restores the max-heap below {@code i} in the first {@code n} pairs. */
    static void siftDown(double[] key, int[] index, int i, int n) {
        while (true) {
            int c = 2 * i + 1;
            if (c >= n) return;
            if (c + 1 < n && after(key[c + 1], index[c + 1], key[c], index[c])) c++;
            if (!after(key[c], index[c], key[i], index[i])) return;
            swap(key, index, i, c);
            i = c;
        }
    }

    static void swap(double[] key, int[] index, int i, int j) {
        double k = key[i];
        key[i] = key[j];
        key[j] = k;
        int x = index[i];
        index[i] = index[j];
        index[j] = x;
    }

    /** Sorts the first {@code n} indices ascending. */
    static void sort(int[] a, int n) {
        for (int i = n / 2 - 1; i >= 0; i--) siftDown(a, i, n);
        for (int end = n - 1; end > 0; end--) {
            int t = a[0];
            a[0] = a[end];
            a[end] = t;
            siftDown(a, 0, end);
        }
    }

    private static void siftDown(int[] a, int i, int n) {
        while (true) {
            int c = 2 * i + 1;
            if (c >= n) return;
            if (c + 1 < n && a[c + 1] > a[c]) c++;
            if (a[c] <= a[i]) return;
            int t = a[i];
            a[i] = a[c];
            a[c] = t;
            i = c;
        }
    }
}
