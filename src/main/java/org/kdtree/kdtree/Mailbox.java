package org.kdtree.kdtree;

import java.util.Arrays;

/**
 * Mailboxing: remembers which primitives the current query (a ray, a sphere) has tested, so
 * that a primitive referenced by several leaves is tested once per query. One int stamp per
 * primitive; a new query takes a new stamp, so nothing is cleared between queries. Per thread,
 * like the query object that owns it.
 */
public final class Mailbox {
    /** Each primitive's last stamp (the ray traversal's hot loops read it directly). */
    final int[] stamp;
    /** The current query's stamp. */
    int ray;

    /**
     * A mailbox for primitives {@code 0 .. primitives - 1}.
     *
     * @param primitives the number of primitives
     */
    public Mailbox(int primitives) {
        stamp = new int[primitives];
    }

    /**
     * {@return true the first time primitive {@code p} is seen in the current query}, marking it seen.
     *
     * @param p the primitive
     */
    public boolean first(int p) {
        if (stamp[p] == ray) return false;
        stamp[p] = ray;
        return true;
    }

    /** {@return the stamp of a new query}, started now (the stamps are cleared once every 2^31 queries). */
    public int next() {
        if (++ray == Integer.MAX_VALUE) {
            Arrays.fill(stamp, 0);
            ray = 1;
        }
        return ray;
    }
}
