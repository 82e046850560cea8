package org.kdtree.kdtree;

/**
 * What becomes of a node once its split is computed and its children's sizes are known: it is
 * split, or it stays a leaf because the split separates nothing (every primitive would go to both
 * children, or, for primitives of zero area whose clipped parts vanish, to neither) or because the children would hold more references than the node's share of the
 * {@link ReferenceBudget}. The two safety nets that read only those sizes, written once for both
 * forms of a node ({@link BoundsSplit}, {@link EventSplit}), so that they cut the same tree.
 */
final class SplitOutcome {
    static final int SPLIT = 0, SEPARATES_NOTHING = 1, OVER_BUDGET = 2;

    private SplitOutcome() {
    }

    /** The outcome for a node of {@code n} primitives whose children would hold {@code left} and {@code right}. */
    static int of(int n, int left, int right, long budget) {
        if (n > 0 && (left == n && right == n || left + right == 0)) return SEPARATES_NOTHING;
        return ReferenceBudget.fits(budget, left, right) ? SPLIT : OVER_BUDGET;
    }
}
