package org.kdtree.testing;

/** A loop that never ends and never looks at its thread's interrupt: what a hung builder does, so that containment is really tested. */
final class Spin {
    private static volatile double x = 1;

    private Spin() {
    }

    /** Spins for ever. */
    static void forever() {
        while (true) x += Math.sqrt(x);
    }
}
