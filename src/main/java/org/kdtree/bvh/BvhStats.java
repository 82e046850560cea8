package org.kdtree.bvh;

import org.kdtree.accel.CostModel;
import org.kdtree.accel.TreeStats;

/**
 * A hierarchy's statistics in the kd-tree's terms ({@link TreeStats}), counted on the binary
 * tree: nodes, leaves, depth, references (each primitive once), memory of both layouts, and the
 * expected cost under the same model as a kd-tree's: Kt for each interior node and Ki for each
 * primitive of each leaf, weighted by the probability {@code SA(box) / SA(root)} that a ray
 * meeting the root meets the node's box.
 */
final class BvhStats {
    private BvhStats() {
    }

    static TreeStats of(Bvh h) {
        int nodes = h.nodeCount(), leaves = 0, empty = 0;
        long depthSum = 0, refs = 0;
        double rootArea = area(h, 0), weighted = 0;
        CostModel cost = h.costModel();
        int[] depth = new int[nodes];
        for (int n = 0; n < nodes; n++) {
            double p = rootArea > 0 ? area(h, n) / rootArea : 1;
            if (h.isLeaf(n)) {
                leaves++;
                int c = h.leafSize(n);
                if (c == 0) empty++;
                refs += c;
                depthSum += depth[n];
                weighted += cost.ki() * c * p;
            } else {
                depth[h.left(n)] = depth[h.right(n)] = depth[n] + 1;
                weighted += cost.kt() * p;
            }
        }
        int nonEmpty = leaves - empty;
        return new TreeStats(nodes, leaves, empty, h.maxDepth(), leaves == 0 ? 0 : (double) depthSum / leaves, refs,
                nonEmpty == 0 ? 0 : (double) refs / nonEmpty, h.memoryBytes(), weighted);
    }

    private static double area(Bvh h, int n) {
        if (h.isLeaf(n) && h.leafSize(n) == 0) return 0;
        return BoxArea.of(h.boxArray(), 2 * h.dimension() * n, h.dimension());
    }
}
