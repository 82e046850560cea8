package org.kdtree.kdtree;

import org.kdtree.accel.TreeStats;
import org.kdtree.geom.Box;

/**
 * The check of a saved tree's arrays before {@link KdTree#restore} trusts them: every node is
 * reached exactly once, depth first in array order, from the root; every link and leaf range is
 * inside its array; every split is a finite plane inside the root voxel; no leaf is deeper than any
 * build goes ({@link KdTreeBuilder#DEPTH_LIMIT}); every reference names one of the primitives. A
 * tree that passes cannot send a query out of its arrays or into a loop, whatever the file held.
 */
final class RestoredLinks {
    private RestoredLinks() {
    }

    /** What the check counts on its way, all of a tree's statistics but the expected cost, which needs the voxels. */
    record Counts(int nodes, int leaves, int empty, int maxDepth, long depthSum, long refs) {
        /**
         * {@return the counts' statistics}, with the expected cost as stated and the memory of the
         * tree's arrays (what the arrays hold, not a statement to check: a file saved before the
         * tracing layout was counted states less)
         * @throws IllegalArgumentException if a count differs from {@code stated}
         */
        TreeStats confirm(TreeStats stated, long memoryBytes) {
            TreeStats counted = KdTreeStats.of(nodes, leaves, empty, maxDepth, depthSum, refs, stated.memoryBytes(), stated.expectedCost());
            if (!counted.equals(stated))
                throw new IllegalArgumentException("the statistics it states (" + stated + ") are not its tree's (" + counted + ")");
            return KdTreeStats.of(nodes, leaves, empty, maxDepth, depthSum, refs, memoryBytes, stated.expectedCost());
        }
    }

    /**
     * {@return the counts of the tree}
     * @throws IllegalArgumentException naming the first node or reference that breaks a rule
     */
    static Counts check(int[] nodes, int[] refs, Box bounds, int primitives) {
        if (nodes.length == 0 || nodes.length % Nodes.INTS != 0)
            throw new IllegalArgumentException("a node array of " + nodes.length + " ints is not whole nodes of " + Nodes.INTS);
        int k = bounds.dimension(), bits = Nodes.axisBits(k), count = nodes.length / Nodes.INTS;
        int[] stack = new int[KdTreeBuilder.DEPTH_LIMIT + 4], depths = new int[stack.length];
        int sp = 0, next = 0, leaves = 0, empty = 0, maxDepth = 0;
        long depthSum = 0, refCount = 0;
        stack[sp++] = 0;
        while (sp > 0) {
            int node = stack[--sp], depth = depths[sp];
            if (node != next)
                throw new IllegalArgumentException("node " + next + " is linked as " + node + ": the nodes are not one tree in depth-first order");
            next++;
            int w = Nodes.word(nodes, node);
            if (Nodes.isLeaf(w, bits)) {
                long start = Nodes.leafStart(nodes, node), end = start + Nodes.leafSize(w, bits);
                if (start < 0 || end > refs.length)
                    throw new IllegalArgumentException("leaf " + node + " holds references " + start + " to " + end + ", outside the "
                            + refs.length + " references");
                leaves++;
                if (end == start) empty++;
                refCount += end - start;
                depthSum += depth;
                maxDepth = Math.max(maxDepth, depth);
                continue;
            }
            int axis = Nodes.axis(w, bits), right = Nodes.rightChild(w, bits), left = Nodes.leftChild(node);
            double xi = Nodes.split(nodes, node);
            if (axis >= k) throw new IllegalArgumentException("node " + node + " splits axis " + axis + " of a " + k + "-D tree");
            if (!(xi >= bounds.min(axis) && xi <= bounds.max(axis)))
                throw new IllegalArgumentException("node " + node + " splits at " + xi + ", outside the root voxel on axis " + axis);
            if (left >= count || right <= left || right >= count)
                throw new IllegalArgumentException("node " + node + " links to children " + left + " and " + right + ", outside the "
                        + count + " nodes");
            if (depth + 1 > KdTreeBuilder.DEPTH_LIMIT)
                throw new IllegalArgumentException("node " + node + " has children at depth " + (depth + 1) + ", deeper than any build goes ("
                        + KdTreeBuilder.DEPTH_LIMIT + ")");
            stack[sp] = right;
            depths[sp++] = depth + 1;
            stack[sp] = left;
            depths[sp++] = depth + 1;
        }
        if (next != count) throw new IllegalArgumentException("nodes " + next + " to " + (count - 1) + " are in no tree");
        for (int i = 0; i < refs.length; i++)
            if (refs[i] < 0 || refs[i] >= primitives)
                throw new IllegalArgumentException("reference " + i + " names primitive " + refs[i] + " of " + primitives);
        return new Counts(count, leaves, empty, maxDepth, depthSum, refCount);
    }
}
