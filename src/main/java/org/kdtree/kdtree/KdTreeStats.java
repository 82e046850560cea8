package org.kdtree.kdtree;

import org.kdtree.accel.CostModel;
import org.kdtree.accel.TreeStats;
import org.kdtree.geom.Box;

/** A kd-tree's {@link TreeStats}, counted in one walk over it. */
final class KdTreeStats {
    private KdTreeStats() {
    }

    /** {@return the statistics of {@code tree}}, counted in one walk over it */
    static TreeStats of(KdTree tree) {
        Walk s = new Walk(tree);
        tree.walk(s);
        return of(s.interiors + s.leaves, s.leaves, s.empty, s.maxDepth, s.depthSum, s.refs, tree.memoryBytes(), s.weightedCost);
    }

    /** {@return the statistics of these counts}: the averages made from them as every tree's are */
    static TreeStats of(int nodes, int leaves, int empty, int maxDepth, long depthSum, long refs, long memoryBytes, double expectedCost) {
        int nonEmpty = leaves - empty;
        return new TreeStats(nodes, leaves, empty, maxDepth, leaves == 0 ? 0 : (double) depthSum / leaves, refs,
                nonEmpty == 0 ? 0 : (double) refs / nonEmpty, memoryBytes, expectedCost);
    }

    /** Counts the statistics of one tree as the walk visits its nodes. */
    private static final class Walk implements TreeVisitor {
        private final double rootArea;
        private final CostModel cost;
        private int interiors, leaves, empty, maxDepth;
        private long depthSum, refs;
        private double weightedCost;

        private Walk(KdTree tree) {
            rootArea = tree.bounds().surfaceArea();
            cost = tree.costModel();
        }

        /**
         * The probability that a ray meeting the root meets this voxel: SA(V) / SA(root). The
         * talk's recursive formula multiplies the ratios child/parent down the path, which
         * telescopes to this. A root of zero area (all primitives at one point) counts 1.
         */
        private double probability(Box voxel) {
            return rootArea > 0 ? voxel.surfaceArea() / rootArea : 1;
        }

        @Override public void interior(int node, int depth, Box voxel, int axis, double split) {
            interiors++;
            weightedCost += cost.kt() * probability(voxel);
        }

        @Override public void leaf(int node, int depth, Box voxel, int from, int to) {
            leaves++;
            int n = to - from;
            if (n == 0) empty++;
            refs += n;
            depthSum += depth;
            maxDepth = Math.max(maxDepth, depth);
            weightedCost += cost.ki() * n * probability(voxel);
        }
    }
}
