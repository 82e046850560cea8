package org.kdtree.measure;

/** The benchmark's random numbers: splitmix64 (bench SPEC, ray set R), bit for bit. */
final class SplitMix64 {
    private long state;

    /**
     * A generator starting from {@code seed}.
     *
     * @param seed the initial state
     */
    public SplitMix64(long seed) {
        state = seed;
    }

    /** {@return the next 64-bit value (unsigned, in a long)} */
    public long nextLong() {
        state += 0x9E3779B97F4A7C15L;
        long z = state;
        z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
        z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
        return z ^ (z >>> 31);
    }

    /** {@return a double in [0, 1): the top 53 bits of the next value times 2^-53} */
    public double nextDouble() {
        return (nextLong() >>> 11) * 0x1.0p-53;
    }
}
