package org.kdtree.bvh;

import org.kdtree.shape.Primitives;

/**
 * The check of a saved hierarchy's arrays before {@link Bvh#restore} trusts them: every node is
 * reached exactly once from the root, each interior node's pair of children after it; every leaf's
 * stretch is inside the leaf order; every box is a box (no NaN, min not above max, unless the leaf
 * is empty); no leaf is deeper than any build goes ({@link BvhBuilder#DEPTH_LIMIT}); every
 * primitive is one of those it is restored over. A hierarchy that passes cannot send a query out
 * of its arrays or into a loop, whatever the file held.
 */
final class RestoredLinks {
    private RestoredLinks() {
    }

    /**
     * {@return the depth of the deepest leaf}
     * @throws IllegalArgumentException naming the first node or primitive that breaks a rule
     */
    static int check(Primitives built, double[] box, int[] link, int[] size, int[] primitives) {
        int k = built.dimension(), count = link.length;
        if (count == 0 || size.length != count || box.length != 2L * k * count)
            throw new IllegalArgumentException(count + " links, " + size.length + " sizes and " + box.length + " box bounds do not make "
                    + "the same nodes of a " + k + "-D hierarchy");
        boolean[] reached = new boolean[count];
        int[] stack = new int[BvhBuilder.DEPTH_LIMIT + 4], depths = new int[stack.length];
        int sp = 0, seen = 0, deepest = 0;
        stack[sp++] = 0;
        while (sp > 0) {
            int node = stack[--sp], depth = depths[sp];
            if (reached[node]) throw new IllegalArgumentException("node " + node + " is linked twice: the nodes are not one tree");
            reached[node] = true;
            seen++;
            deepest = Math.max(deepest, depth);
            checkBox(box, k, node, link[node] < 0 && size[node] == 0);
            if (link[node] < 0) {
                long first = ~link[node], end = first + size[node];
                if (size[node] < 0 || end > primitives.length)
                    throw new IllegalArgumentException("leaf " + node + " holds primitives " + first + " to " + end + " of the leaf order, outside its "
                            + primitives.length);
                continue;
            }
            int left = link[node];
            if (left <= node || left + 1 >= count || size[node] != 0)
                throw new IllegalArgumentException("node " + node + " links to children " + left + " and " + (left + 1L) + ", outside the "
                        + count + " nodes after it");
            if (depth + 1 > BvhBuilder.DEPTH_LIMIT)
                throw new IllegalArgumentException("node " + node + " has children at depth " + (depth + 1) + ", deeper than any build goes ("
                        + BvhBuilder.DEPTH_LIMIT + ")");
            stack[sp] = left + 1;
            depths[sp++] = depth + 1;
            stack[sp] = left;
            depths[sp++] = depth + 1;
        }
        if (seen != count) throw new IllegalArgumentException((count - seen) + " of the " + count + " nodes are in no tree");
        for (int i = 0; i < primitives.length; i++)
            if (primitives[i] < 0 || primitives[i] >= built.size())
                throw new IllegalArgumentException("position " + i + " of the leaf order names primitive " + primitives[i] + " of " + built.size());
        return deepest;
    }

    private static void checkBox(double[] box, int k, int node, boolean emptyLeaf) {
        for (int a = 0; a < k; a++) {
            double lo = box[2 * k * node + a], hi = box[2 * k * node + k + a];
            if (Double.isNaN(lo) || Double.isNaN(hi) || !emptyLeaf && lo > hi)
                throw new IllegalArgumentException("node " + node + " has the box " + lo + " .. " + hi + " on axis " + a);
        }
    }
}
