package org.kdtree.build;

/**
 * Sorts events, kept as parallel arrays of positions and int codes, by position. Only the
 * position order matters: the sweep counts the kinds of all events at one position together.
 *
 * <p>Large arrays (the root's events) go through an LSD radix sort on the order-preserving
 * bits of the doubles, skipping the digits where all keys agree (most of the exponent);
 * small ones (a node's straddlers) through insertion or merge sort. No objects per event.
 */
final class EventSort {
    private static final int INSERTION = 32;
    private static final int RADIX_MIN = 2048;
    private static final int DIGIT_BITS = 11;
    private static final int BUCKETS = 1 << DIGIT_BITS;

    private EventSort() {
    }

    /** Sorts {@code pos[from..to)} ascending, moving {@code code} along. */
    static void sort(double[] pos, int[] code, int from, int to) {
        int n = to - from;
        if (n <= INSERTION) insertion(pos, code, from, to);
        else if (from == 0) sort(pos, code, n);
        else {
            double[] p = java.util.Arrays.copyOfRange(pos, from, to);
            int[] c = java.util.Arrays.copyOfRange(code, from, to);
            sort(p, c, n);
            System.arraycopy(p, 0, pos, from, n);
            System.arraycopy(c, 0, code, from, n);
        }
    }

    /** Sorts {@code pos[0..n)} ascending, moving {@code code} along. */
    static void sort(double[] pos, int[] code, int n) {
        if (n <= INSERTION) insertion(pos, code, 0, n);
        else if (n < RADIX_MIN) mergeSort(pos, code, n);
        else radix(pos, code, n);
    }

    /** Unsigned-comparable bits of a double: the order of the doubles (with -0.0 below 0.0). */
    static long key(double x) {
        long b = Double.doubleToRawLongBits(x);
        return b < 0 ? ~b : b ^ Long.MIN_VALUE;
    }

    private static void insertion(double[] pos, int[] code, int from, int to) {
        for (int i = from + 1; i < to; i++) {
            double p = pos[i];
            int c = code[i];
            int j = i - 1;
            while (j >= from && pos[j] > p) {
                pos[j + 1] = pos[j];
                code[j + 1] = code[j];
                j--;
            }
            pos[j + 1] = p;
            code[j + 1] = c;
        }
    }

    private static void mergeSort(double[] pos, int[] code, int n) {
        double[] tp = new double[n];
        int[] tc = new int[n];
        for (int i = 0; i < n; i += INSERTION) insertion(pos, code, i, Math.min(n, i + INSERTION));
        double[] sp = pos, dp = tp;
        int[] sc = code, dc = tc;
        for (int w = INSERTION; w < n; w *= 2) {
            for (int lo = 0; lo < n; lo += 2 * w) {
                int mid = Math.min(n, lo + w), hi = Math.min(n, lo + 2 * w);
                merge(sp, sc, lo, mid, sp, sc, mid, hi, dp, dc, lo);
            }
            double[] t = sp; sp = dp; dp = t;
            int[] u = sc; sc = dc; dc = u;
        }
        if (sp != pos) {
            System.arraycopy(sp, 0, pos, 0, n);
            System.arraycopy(sc, 0, code, 0, n);
        }
    }

    /** Merges two sorted runs {@code a[ia..ea)} and {@code b[ib..eb)} into {@code d} from {@code at}. */
    static int merge(double[] ap, int[] ac, int ia, int ea, double[] bp, int[] bc, int ib, int eb,
                     double[] dp, int[] dc, int at) {
        while (ia < ea && ib < eb) {
            if (bp[ib] < ap[ia]) { dp[at] = bp[ib]; dc[at++] = bc[ib++]; }
            else { dp[at] = ap[ia]; dc[at++] = ac[ia++]; }
        }
        while (ia < ea) { dp[at] = ap[ia]; dc[at++] = ac[ia++]; }
        while (ib < eb) { dp[at] = bp[ib]; dc[at++] = bc[ib++]; }
        return at;
    }

    private static void radix(double[] pos, int[] code, int n) {
        long[] keys = new long[n], k2 = new long[n];
        int[] c2 = new int[n];
        long and = -1L, or = 0;
        for (int i = 0; i < n; i++) {
            long k = key(pos[i]);
            keys[i] = k;
            and &= k;
            or |= k;
        }
        long varying = and ^ or;
        long[] sk = keys, dk = k2;
        int[] sc = code, dc = c2;
        int[] count = new int[BUCKETS];
        for (int shift = 0; shift < 64; shift += DIGIT_BITS) {
            if (((varying >>> shift) & (BUCKETS - 1)) == 0) continue;
            java.util.Arrays.fill(count, 0);
            for (int i = 0; i < n; i++) count[(int) (sk[i] >>> shift) & (BUCKETS - 1)]++;
            int sum = 0;
            for (int b = 0; b < BUCKETS; b++) { int c = count[b]; count[b] = sum; sum += c; }
            for (int i = 0; i < n; i++) {
                int at = count[(int) (sk[i] >>> shift) & (BUCKETS - 1)]++;
                dk[at] = sk[i];
                dc[at] = sc[i];
            }
            long[] t = sk; sk = dk; dk = t;
            int[] u = sc; sc = dc; dc = u;
        }
        if (sc != code) System.arraycopy(sc, 0, code, 0, n);
        for (int i = 0; i < n; i++) pos[i] = fromKey(sk[i]);
    }

    private static double fromKey(long k) {
        long b = k < 0 ? k ^ Long.MIN_VALUE : ~k;
        return Double.longBitsToDouble(b);
    }
}
