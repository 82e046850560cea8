package org.kdtree.collide;

import java.util.Arrays;

/**
 * Mailboxing for sphere queries: a primitive referenced by several leaves is tested once per
 * query. One int stamp per primitive; each query takes a new stamp, so nothing is cleared between
 * queries. Owned by one query object, like its stack.
 */
final class TestedOnce {
    private final int[] stamp;
    private int query;

    TestedOnce(int primitives) {
        stamp = new int[primitives];
    }

    /** Starts a new query (clearing the stamps once every 2^31 queries). */
    void next() {
        if (++query == Integer.MAX_VALUE) {
            Arrays.fill(stamp, 0);
            query = 1;
        }
    }

    /** True the first time primitive {@code p} is seen in this query. */
    boolean first(int p) {
        if (stamp[p] == query) return false;
        stamp[p] = query;
        return true;
    }
}
