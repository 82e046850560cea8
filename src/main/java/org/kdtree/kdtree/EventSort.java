package org.kdtree.kdtree;

/**
 * Sorts events, kept as parallel arrays of positions and int codes, by position. Only the
 * position order matters: the sweep counts the kinds of all events at one position together.
 *
 * <p>Large ranges (the root's events) go through an LSD radix sort on the order-preserving
 * bits of the doubles, skipping the digits where all keys agree (most of the exponent);
 * small ones (a node's straddlers) through insertion sort, and the ones between through a
 * merge sort. Both work in the caller's scratch arrays: no objects per event, no allocation.
 */
final class EventSort {
    private static final int INSERTION = 32;
    private static final int RADIX_MIN = 2048;
    private static final int DIGIT_BITS = 11;
    private static final int BUCKETS = 1 << DIGIT_BITS;

    private EventSort() {
    }

    /**
     * Sorts {@code pos[from..to)} ascending, moving {@code code} along; {@code tmpPos} and
     * {@code tmpCode} are scratch for at least {@code to - from} events.
     */
    static void sort(double[] pos, int[] code, int from, int to, double[] tmpPos, int[] tmpCode) {
        int n = to - from;
        if (n <= INSERTION) insertion(pos, code, from, to);
        else if (n < RADIX_MIN) mergeSort(pos, code, from, n, tmpPos, tmpCode);
        else radix(pos, code, from, n, tmpPos, tmpCode);
    }

    /** Unsigned-comparable bits of a double: the order of the doubles (with -0.0 below 0.0). */
    private static long key(double x) {
        long b = Double.doubleToRawLongBits(x);
        return b < 0 ? ~b : b ^ Long.MIN_VALUE;
    }

    /** Sorts {@code pos[from, to)} by position, stably, carrying {@code code} along: for short runs. */
    static void insertion(double[] pos, int[] code, int from, int to) {
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

    /** Runs of {@link #INSERTION} sorted in place, then merged pairwise through the scratch arrays. */
    private static void mergeSort(double[] pos, int[] code, int from, int n, double[] tp, int[] tc) {
        for (int i = 0; i < n; i += INSERTION) insertion(pos, code, from + i, from + Math.min(n, i + INSERTION));
        double[] sp = pos, dp = tp;
        int[] sc = code, dc = tc;
        int sAt = from, dAt = 0;
        for (int w = INSERTION; w < n; w *= 2) {
            for (int lo = 0; lo < n; lo += 2 * w) {
                int mid = Math.min(n, lo + w), hi = Math.min(n, lo + 2 * w);
                merge(sp, sc, sAt + lo, sAt + mid, sAt + hi, dp, dc, dAt + lo);
            }
            double[] t = sp; sp = dp; dp = t;
            int[] u = sc; sc = dc; dc = u;
            int v = sAt; sAt = dAt; dAt = v;
        }
        copyBack(sp, sc, sAt, pos, code, from, n);
    }

    /** Merges the sorted runs {@code [ia, mid)} and {@code [mid, end)} of one array into {@code d} from {@code at}. */
    private static void merge(double[] p, int[] c, int ia, int mid, int end, double[] dp, int[] dc, int at) {
        int ib = mid;
        while (ia < mid && ib < end) {
            if (p[ib] < p[ia]) { dp[at] = p[ib]; dc[at++] = c[ib++]; }
            else { dp[at] = p[ia]; dc[at++] = c[ia++]; }
        }
        while (ia < mid) { dp[at] = p[ia]; dc[at++] = c[ia++]; }
        while (ib < end) { dp[at] = p[ib]; dc[at++] = c[ib++]; }
    }

    /**
     * LSD radix sort of {@code pos[from .. from + n)} on {@link #key}, recomputed from the doubles
     * at each pass, ping-ponging through {@code tp} and {@code tc}: nothing is allocated but the
     * bucket counts.
     */
    private static void radix(double[] pos, int[] code, int from, int n, double[] tp, int[] tc) {
        long and = -1L, or = 0;
        for (int i = from; i < from + n; i++) {
            long k = key(pos[i]);
            and &= k;
            or |= k;
        }
        long varying = and ^ or;
        double[] sp = pos, dp = tp;
        int[] sc = code, dc = tc;
        int sAt = from, dAt = 0;
        int[] count = new int[BUCKETS];
        for (int shift = 0; shift < 64; shift += DIGIT_BITS) {
            if (((varying >>> shift) & (BUCKETS - 1)) == 0) continue;
            java.util.Arrays.fill(count, 0);
            for (int i = sAt; i < sAt + n; i++) count[digit(sp[i], shift)]++;
            for (int b = 0, sum = 0; b < BUCKETS; b++) { int c = count[b]; count[b] = sum; sum += c; }
            for (int i = sAt; i < sAt + n; i++) {
                int at = dAt + count[digit(sp[i], shift)]++;
                dp[at] = sp[i];
                dc[at] = sc[i];
            }
            double[] t = sp; sp = dp; dp = t;
            int[] u = sc; sc = dc; dc = u;
            int v = sAt; sAt = dAt; dAt = v;
        }
        copyBack(sp, sc, sAt, pos, code, from, n);
    }

    private static int digit(double x, int shift) {
        return (int) (key(x) >>> shift) & (BUCKETS - 1);
    }

    /** Copies the sorted run {@code [sAt, sAt + n)} of {@code sp, sc} back to {@code pos, code} at {@code from}, unless it is already there. */
    private static void copyBack(double[] sp, int[] sc, int sAt, double[] pos, int[] code, int from, int n) {
        if (sp == pos) return;
        System.arraycopy(sp, sAt, pos, from, n);
        System.arraycopy(sc, sAt, code, from, n);
    }
}
