package org.kdtree.traverse;

import java.util.Arrays;

/**
 * Mailboxing: remembers which primitives the current ray has tested, so that a primitive
 * referenced by several leaves is tested once per ray. One int stamp per primitive; a new ray
 * takes a new stamp, so nothing is cleared between rays. Per thread, like the traverser.
 */
final class Mailbox {
    final int[] stamp;
    int ray;

    Mailbox(int primitives) {
        stamp = new int[primitives];
    }

    /** Starts a new ray and returns its stamp (clearing the stamps once every 2^31 rays). */
    int next() {
        if (++ray == Integer.MAX_VALUE) {
            Arrays.fill(stamp, 0);
            ray = 1;
        }
        return ray;
    }
}
