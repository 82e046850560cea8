package org.kdtree.tradeoff;

/** The ways a nearest-neighbour study answers its queries: one series of its chart each. */
enum NeighbourSearch {
    /** Every point scanned: the baseline, always exact. */
    BRUTE_FORCE("brute force"),
    /** The kd-tree's exact search. */
    EXACT("exact kd-tree"),
    /** Best-bin-first with a budget of leaves ({@code NearestQuery.maxLeaves}). */
    BEST_BIN_FIRST("best-bin-first"),
    /** The (1 + eps) bound ({@code NearestQuery.epsilon}). */
    EPSILON("epsilon");

    private final String label;

    NeighbourSearch(String label) {
        this.label = label;
    }

    /** {@return how tables, CSV files and legends name it} */
    public String label() {
        return label;
    }
}
