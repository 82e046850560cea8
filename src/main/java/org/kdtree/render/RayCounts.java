package org.kdtree.render;

import java.util.Arrays;

/** Rays cast by kind. Not thread-safe: one per thread, merged at the end. */
final class RayCounts {
    private final long[] counts = new long[RayKind.values().length];

    /**
     * Counts one ray of {@code kind}.
     *
     * @param kind the ray's kind
     */
    public void add(RayKind kind) { counts[kind.ordinal()]++; }

    /**
     * Counts {@code n} rays of {@code kind}.
     *
     * @param kind the rays' kind
     * @param n    how many
     */
    public void add(RayKind kind, int n) { counts[kind.ordinal()] += n; }

    /**
     * {@return the rays of {@code kind} counted}
     *
     * @param kind the kind
     */
    public long get(RayKind kind) { return counts[kind.ordinal()]; }

    /** {@return the rays of all kinds counted} */
    public long total() { return Arrays.stream(counts).sum(); }

    /**
     * Adds all of {@code other}'s counts to this.
     *
     * @param other the counts to add
     */
    public void merge(RayCounts other) {
        for (int i = 0; i < counts.length; i++) counts[i] += other.counts[i];
    }

    @Override public String toString() {
        StringBuilder s = new StringBuilder();
        for (RayKind k : RayKind.values()) s.append(s.length() > 0 ? ", " : "").append(k.label()).append('=').append(get(k));
        return s.toString();
    }
}
