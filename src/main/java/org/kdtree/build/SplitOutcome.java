package org.kdtree.build;

import java.util.concurrent.CancellationException;

/**
 * What becomes of a node once its split is computed and its children's sizes are known: it is
 * split, or it stays a leaf because the split separates nothing (every primitive would go to both
 * children, or, for primitives of zero area whose clipped parts vanish, to neither) or because the children would hold more references than the node's share of the
 * {@link ReferenceBudget}. The two safety nets that read only those sizes, written once for the
 * recursion and both engines, so that all of them cut the same tree.
 *
 * <p>Every split node of every builder passes here, so this is also where a build stops when its
 * thread is interrupted (the workbench cancels a stale build so): it throws
 * {@link CancellationException}. Forked subtrees of a parallel build run on pool threads and
 * finish on their own.
 */
final class SplitOutcome {
    static final int SPLIT = 0, SEPARATES_NOTHING = 1, OVER_BUDGET = 2;

    private SplitOutcome() {
    }

    /** The outcome for a node of {@code n} primitives whose children would hold {@code left} and {@code right}. */
    static int of(int n, int left, int right, long budget) {
        if (Thread.currentThread().isInterrupted()) throw new CancellationException("build cancelled");
        if (n > 0 && (left == n && right == n || left + right == 0)) return SEPARATES_NOTHING;
        return ReferenceBudget.fits(budget, left, right) ? SPLIT : OVER_BUDGET;
    }
}
