package org.kdtree.kdtree;

/**
 * The events of one axis of a large node (the root's), made and sorted as one {@code long} each,
 * as Sunflow's kd-tree does: the order-preserving bits of the position rounded down to a float
 * in the high 32 bits, the event's {@link EventCode} in the low 32, and its exact position carried
 * alongside. One LSD radix sort on the high 32 bits only (three 11-bit digits, fewer where
 * every key agrees) moves 16 bytes an event three times, where a sort of the doubles themselves
 * goes through six digits. (The position is carried, not looked up from the reference after the
 * sort: that look-up, in the order of the sorted events, misses the cache nearly every time.)
 *
 * <p>The events come out in exactly the order of {@link EventSort}'s stable sort of the doubles:
 * made in slot order (a start before its end), kept so by the stable radix sort among equal
 * float keys, and each run of equal float keys (positions closer than a float's ulp) then
 * sorted by its exact doubles, stably, by insertion. So the exact trees do not change.
 */
final class PackedEventSort {
    private static final int DIGIT_BITS = 11;
    private static final int BUCKETS = 1 << DIGIT_BITS;

    private PackedEventSort() {
    }

    /**
     * Writes the events on {@code axis} of the {@code n} references {@code refs[at ..]} (clipped
     * bounds at the same slots of {@code bounds}, {@code 2k} values a slot) into
     * {@code pos, code [from, from + events)}, sorted; {@code keys}, {@code tmpKeys} and
     * {@code tmpPos} are scratch for at least {@code events} values, {@code count} for
     * {@link #countLength()} ints.
     */
    static void write(double[] bounds, int k, int[] refs, int at, int n, int axis, double[] pos, int[] code, int from,
                      long[] keys, long[] tmpKeys, double[] tmpPos, int[] count) {
        int m = 0;
        for (int j = 0, o = 2 * k * at + axis; j < n; j++, o += 2 * k) {
            double lo = bounds[o], hi = bounds[o + k];
            int prim = refs[at + j];
            if (lo == hi) {
                pos[from + m] = lo;
                keys[m++] = high(lo) | low(EventCode.PLANAR, prim);
            } else {
                pos[from + m] = lo;
                keys[m++] = high(lo) | low(EventCode.START, prim);
                pos[from + m] = hi;
                keys[m++] = high(hi) | low(EventCode.END, prim);
            }
        }
        radix(keys, pos, from, tmpKeys, tmpPos, m, count, code);
        fixRuns(keys, pos, code, from, m);
    }

    /** The low 32 bits of a key: the event's code, riding along unsorted. */
    private static long low(int kind, int primitive) {
        return EventCode.of(kind, primitive) & 0xFFFF_FFFFL;
    }

    /** {@return the ints {@link #write} needs in {@code count}} */
    static int countLength() { return 3 * BUCKETS; }

    /** The high 32 bits of a key: the unsigned-comparable bits of {@code x} rounded down to a float. */
    private static long high(double x) {
        float f = (float) x;
        if (f > x) f = Math.nextDown(f);   // round down, so that the float order never contradicts the doubles'
        int b = Float.floatToRawIntBits(f);
        int u = b < 0 ? ~b : b ^ Integer.MIN_VALUE;
        return (long) u << 32;
    }

    /**
     * LSD radix sort of {@code keys[0, n)} on bits 32..63 (the lower bits ride along in their
     * original order), each key's exact position {@code pos[from + i]} moving with it, ping-ponging
     * through {@code tk} and {@code tp}; the three histograms are counted in one pass. The sorted
     * keys end in {@code keys}, the positions in {@code pos} and the codes (the keys' low bits) in {@code code}.
     */
    private static void radix(long[] keys, double[] pos, int from, long[] tk, double[] tp, int n, int[] count, int[] code) {
        java.util.Arrays.fill(count, 0, 3 * BUCKETS, 0);
        long and = -1L, or = 0;
        for (int i = 0; i < n; i++) {
            long key = keys[i];
            and &= key;
            or |= key;
            count[digit(key, 0)]++;
            count[BUCKETS + digit(key, 1)]++;
            count[2 * BUCKETS + digit(key, 2)]++;
        }
        long varying = and ^ or;
        long[] sk = keys, dk = tk;
        double[] sp = pos, dp = tp;
        int sAt = from, dAt = 0;
        for (int p = 0; p < 3; p++) {
            if (((varying >>> (32 + p * DIGIT_BITS)) & (BUCKETS - 1)) == 0) continue;
            int base = p * BUCKETS;
            for (int i = base, sum = 0; i < base + BUCKETS; i++) { int c = count[i]; count[i] = sum; sum += c; }
            for (int i = 0; i < n; i++) {
                long key = sk[i];
                int to = count[base + digit(key, p)]++;
                dk[to] = key;
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
        for (int i = 0; i < n; i++) code[from + i] = (int) keys[i];
    }

    /** Digit p (0 lowest) of a key's high 32 bits; the top digit has 10 bits. */
    private static int digit(long key, int p) {
        return (int) (key >>> (32 + p * DIGIT_BITS)) & (BUCKETS - 1);
    }

    /**
     * Sorts each run of events with equal float keys by their exact positions, stably (insertion):
     * such runs are positions closer than a float's ulp, and nearly always one event long or
     * already equal.
     */
    private static void fixRuns(long[] sorted, double[] pos, int[] code, int from, int n) {
        for (int i = 0; i < n; ) {
            long run = sorted[i] >>> 32;
            int end = i + 1;
            while (end < n && sorted[end] >>> 32 == run) end++;
            if (end - i > 1) EventSort.insertion(pos, code, from + i, from + end);
            i = end;
        }
    }
}
