package org.kdtree.kdtree;

/**
 * The rule that keeps every build bounded in references, and so in memory and time, whatever
 * the geometry: the root may hold {@code B N} references (B per input primitive, default
 * {@link KdTreeBuilder#REFERENCE_BUDGET}), and a split passes its node's budget on to
 * its children in proportion to the references each receives. A split whose children would hold
 * more references than the node's budget makes a leaf instead. The leaves' budgets add up to the
 * root's and each leaf holds no more than its budget, so a tree never holds more than {@code B N}
 * references.
 *
 * <p>On meshes the budget is far from binding: the exact SAH tree of the Stanford bunny holds 5.3
 * references per triangle. It binds where primitives overlap without end (a fan of thousands of
 * slivers sharing a vertex, coincident triangles), and the tree reports how many leaves it made
 * early ({@link org.kdtree.kdtree.KdTree#budgetLeaves()}). The rule uses the node's and children's
 * sizes only, so every builder, algorithm and thread count makes the same decision.
 */
final class ReferenceBudget {
    private ReferenceBudget() {
    }

    /** The root's budget: {@code perPrimitive} references for each of the {@code n} primitives (at least one). */
    static long root(int perPrimitive, int n) {
        return (long) perPrimitive * Math.max(1, n);
    }

    /** Whether a split into {@code left + right} references stays within {@code budget}. */
    static boolean fits(long budget, int left, int right) {
        return (long) left + right <= budget;
    }

    /**
     * A child's share of its parent's budget: {@code floor(budget size / (left + right))}, exact in 64 bits;
     * nothing for the children of an empty node (a builder may split one).
     */
    static long share(long budget, int size, int left, int right) {
        long sum = (long) left + right;
        if (sum == 0) return 0;
        return budget / sum * size + budget % sum * size / sum;
    }
}
