package org.kdtree.kdtree;

/**
 * The one sort of events (positions and {@link EventCode}s in parallel arrays) by position, as
 * Sunflow's kd-tree sorts them: each event packed in one {@code long}, the order-preserving bits
 * of its position rounded down to a float in the high 32 bits, its code in the low 32, the exact
 * position carried alongside; one LSD radix sort on the high bits (three 11-bit digits, skipping
 * those where every key agrees); then each run of equal float keys (positions closer than a
 * float's ulp) put in the order of the doubles by insertion. A few events go by insertion alone.
 * Either way the order is that of a stable sort of the doubles (-0.0 may come before or after
 * 0.0: the sweep counts equal positions together). Scratch lives in the instance, one per
 * thread of a build: nothing is allocated once it has grown.
 */
final class EventSort {
    /** At most this many events are sorted by insertion alone. */
    static final int INSERTION = 32;
    private static final int DIGIT_BITS = 11, BUCKETS = 1 << DIGIT_BITS;

    private long[] keys = new long[0], tmpKeys = new long[0];
    private double[] tmpPos = new double[0];
    private final int[] count = new int[3 * BUCKETS];

    /** Sorts {@code pos[from, to)} ascending, moving {@code code} along. */
    void sort(double[] pos, int[] code, int from, int to) {
        int n = to - from;
        if (n <= INSERTION) {
            insertion(pos, code, from, to);
            return;
        }
        if (keys.length < n) {
            keys = new long[NodeStore.grown(keys.length, n)];
            tmpKeys = new long[keys.length];
            tmpPos = new double[keys.length];
        }
        for (int i = 0; i < n; i++) keys[i] = high(pos[from + i]) | code[from + i] & 0xFFFF_FFFFL;
        radix(pos, from, n);
        for (int i = 0; i < n; i++) code[from + i] = (int) keys[i];
        for (int i = 0; i < n; ) {   // runs of equal float keys, nearly always one event long
            int end = i + 1;
            while (end < n && keys[end] >>> 32 == keys[i] >>> 32) end++;
            if (end - i > 1) insertion(pos, code, from + i, from + end);
            i = end;
        }
    }

    /** The high 32 bits of a key: the unsigned-comparable bits of {@code x} rounded down to a float. */
    private static long high(double x) {
        float f = (float) x;
        if (f > x) f = Math.nextDown(f);   // round down, so that the float order never contradicts the doubles'
        int b = Float.floatToRawIntBits(f);
        return (long) (b < 0 ? ~b : b ^ Integer.MIN_VALUE) << 32;
    }

    /**
     * LSD radix sort of {@code keys[0, n)} on bits 32..63 (the low bits ride along), each key's
     * position {@code pos[from + i]} moving with it, through the scratch arrays; the three
     * histograms are counted in one pass. The keys end in {@link #keys}, the positions in {@code pos}.
     */
    private void radix(double[] pos, int from, int n) {
        java.util.Arrays.fill(count, 0);
        long and = -1L, or = 0;
        for (int i = 0; i < n; i++) {
            long key = keys[i];
            and &= key;
            or |= key;
            for (int p = 0; p < 3; p++) count[p * BUCKETS + digit(key, p)]++;
        }
        long[] sk = keys, dk = tmpKeys;
        double[] sp = pos, dp = tmpPos;
        int sAt = from, dAt = 0;
        for (int p = 0; p < 3; p++) {
            if (digit(and ^ or, p) == 0) continue;
            for (int i = p * BUCKETS, sum = 0; i < (p + 1) * BUCKETS; i++) { int c = count[i]; count[i] = sum; sum += c; }
            for (int i = 0; i < n; i++) {
                int to = count[p * BUCKETS + digit(sk[i], p)]++;
                dk[to] = sk[i];
                dp[dAt + to] = sp[sAt + i];
            }
            long[] t = sk; sk = dk; dk = t;
            double[] u = sp; sp = dp; dp = u;
            int v = sAt; sAt = dAt; dAt = v;
        }
        if (sk != keys) {
            System.arraycopy(sk, 0, keys, 0, n);
            System.arraycopy(sp, sAt, pos, from, n);
        }
    }

    /** Digit p (0 lowest) of a key's high 32 bits; the top digit has 10 bits. */
    private static int digit(long key, int p) {
        return (int) (key >>> (32 + p * DIGIT_BITS)) & (BUCKETS - 1);
    }

    /** Sorts {@code pos[from, to)} by position, stably, carrying {@code code} along: for short runs. */
    static void insertion(double[] pos, int[] code, int from, int to) {
        for (int i = from + 1; i < to; i++) {
            double p = pos[i];
            int c = code[i], j = i - 1;
            for (; j >= from && pos[j] > p; j--) {
                pos[j + 1] = pos[j];
                code[j + 1] = code[j];
            }
            pos[j + 1] = p;
            code[j + 1] = c;
        }
    }
}
