package org.kdtree.testing;

import static org.assertj.core.api.Assertions.assertThat;

import org.kdtree.kdtree.KdTree;

/** Tree comparisons for tests. */
public final class Trees {
    private Trees() {
    }

    /** Asserts two trees are identical: same nodes, same splits, same leaves with the same references. */
    public static void assertSameTree(KdTree a, KdTree b) {
        assertSameTree(a, b, "");
    }

    /**
     * {@link #assertSameTree(KdTree, KdTree)}, naming the case in every message.
     *
     * @param a the expected tree
     * @param b the tree checked against it
     * @param what the case, for the messages
     */
    public static void assertSameTree(KdTree a, KdTree b, String what) {
        assertThat(b.nodeCount()).as("node count %s", what).isEqualTo(a.nodeCount());
        assertThat(b.nodeArray()).as("nodes (axes and children or leaf sizes; splits or leaf offsets) %s", what)
                .isEqualTo(a.nodeArray());
        assertThat(b.bounds()).as("root voxel %s", what).isEqualTo(a.bounds());
        assertThat(b.refArray()).as("leaf references %s", what).isEqualTo(a.refArray());
    }
}
