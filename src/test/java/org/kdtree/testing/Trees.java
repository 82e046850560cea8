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
        assertThat(b.wordArray()).as("node words (axes, children)").isEqualTo(a.wordArray());
        assertThat(b.splitArray()).as("split positions").isEqualTo(a.splitArray());
        assertThat(b.leafStartArray()).as("leaf sizes").isEqualTo(a.leafStartArray());
        assertThat(b.refArray()).as("leaf references").isEqualTo(a.refArray());
    }
}
