package org.kdtree.traverse;

import java.util.Map;
import java.util.WeakHashMap;
import org.kdtree.tree.KdTree;

/**
 * The layout the fast 3-D path reads: one {@code long[]} with two slots per node, so that a
 * node costs one cache line instead of two (the tree's split and word arrays are separate).
 * Interior node n: slot {@code 2n} holds the split position's bits, slot {@code 2n+1}
 * {@code rightChild << 5 | axis}. Leaf: slot {@code 2n} the first index into the shared
 * reference array, slot {@code 2n+1} {@code count << 5 | 31} (no leafStart indirection). The
 * fixed 5-bit axis field is this copy's own (the tree's is as wide as its dimension needs).
 * Built once per tree and shared by all traversers (read-only).
 */
final class PackedTree {
    private static final Map<KdTree, PackedTree> CACHE = new WeakHashMap<>();

    final long[] nodes;
    final int[] refs;

    private PackedTree(KdTree tree) {
        int n = tree.nodeCount();
        nodes = new long[2 * n];
        int[] word = tree.wordArray();
        double[] split = tree.splitArray();
        int[] leafStart = tree.leafStartArray();
        int mark = tree.leafMark(), shift = tree.axisBits();
        for (int i = 0; i < n; i++) {
            int w = word[i];
            if ((w & mark) == mark) {
                int leaf = w >>> shift;
                nodes[2 * i] = leafStart[leaf];
                nodes[2 * i + 1] = ((long) (leafStart[leaf + 1] - leafStart[leaf]) << 5) | 31;
            } else {
                nodes[2 * i] = Double.doubleToRawLongBits(split[i]);
                nodes[2 * i + 1] = ((long) (w >>> shift) << 5) | (w & mark);
            }
        }
        refs = tree.refArray();
    }

    /** The packed form of {@code tree}, made on first use. */
    static synchronized PackedTree of(KdTree tree) {
        return CACHE.computeIfAbsent(tree, PackedTree::new);
    }
}
