package org.kdtree.testing;

import static org.assertj.core.api.Assertions.assertThat;

import org.kdtree.tree.KdTree;

/** Tree comparisons for tests. */
public final class Trees {
    private Trees() {
    }

    /** Asserts two trees are identical: same nodes, same splits, same leaves with the same references. */
    public static void assertSameTree(KdTree a, KdTree b) {
        assertThat(b.nodeCount()).as("node count").isEqualTo(a.nodeCount());
        assertThat(b.nodeArray()).as("nodes (split codes or leaf offsets; axes, children or leaf sizes)").isEqualTo(a.nodeArray());
        assertThat(b.bounds()).as("root voxel (the grid of split positions)").isEqualTo(a.bounds());
        assertThat(b.refArray()).as("leaf references").isEqualTo(a.refArray());
    }
}
