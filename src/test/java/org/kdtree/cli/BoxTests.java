package org.kdtree.cli;

import static org.junit.jupiter.api.Assertions.fail;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

/**
 * What a test that grades in a box needs: a box this machine can make (bubblewrap, and on root
 * util-linux's tools). Without one the test is skipped with one line on the console saying why
 * and what to install, as the robot tests are without a display; where the run requires every box
 * test ({@code -Dkdtree.requireBox=true}, which {@code .ci/run} sets) it fails instead, so that
 * CI cannot pass with them skipped.
 */
final class BoxTests {
    /** Set on the test run to make a missing box a failure, not a skip. */
    static final String REQUIRED = "kdtree.requireBox";
    private static String unavailable;
    private static boolean looked, said;

    private BoxTests() {
    }

    /** Skips (or, when required, fails) the calling test unless a box can be made here. */
    static synchronized void assumeABoxCanBeMade() {
        if (!looked) {
            looked = true;
            try {
                StudentBox.find();
            } catch (StudentBox.Unavailable e) {
                unavailable = e.getMessage();
            }
        }
        if (unavailable == null) return;
        String why = "no box can be made here (" + unavailable + ")";
        if (Boolean.getBoolean(REQUIRED)) fail("the box tests are required (-D" + REQUIRED + "=true) and " + why);
        if (!said) System.err.println("SKIPPED the grading-in-a-box tests: " + why);
        said = true;
        assumeTrue(false, why);
    }
}
