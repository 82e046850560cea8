package org.kdtree.accel;

/**
 * Statistics of a built structure (a kd-tree, a bounding volume hierarchy), enough to compare any two.
 *
 * @param nodes               interior nodes plus leaves
 * @param leaves              leaves
 * @param emptyLeaves         leaves with no primitive
 * @param maxDepth            depth of the deepest leaf (the root has depth 0)
 * @param averageLeafDepth    mean depth over all leaves
 * @param references          primitive references stored in leaves (a primitive counts once per leaf)
 * @param averageRefsPerLeaf  references per non-empty leaf
 * @param memoryBytes         bytes held by the tree's arrays
 * @param expectedCost        the SAH cost of the whole tree (talk, section 3.3.1)
 */
public record TreeStats(int nodes, int leaves, int emptyLeaves, int maxDepth, double averageLeafDepth,
                        long references, double averageRefsPerLeaf, long memoryBytes, double expectedCost) {

    /** {@return several lines of "name: value", for the command line} */
    public String describe() {
        return String.format(java.util.Locale.ROOT,
                "nodes: %d%nleaves: %d%nempty leaves: %d%nmax depth: %d%naverage leaf depth: %.2f%n"
                        + "references: %d%nreferences per non-empty leaf: %.2f%nmemory: %d bytes%nexpected cost: %.2f",
                nodes, leaves, emptyLeaves, maxDepth, averageLeafDepth, references, averageRefsPerLeaf,
                memoryBytes, expectedCost);
    }
}
