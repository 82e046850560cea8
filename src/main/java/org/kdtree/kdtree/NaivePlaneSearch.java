package org.kdtree.kdtree;

import java.util.Arrays;

/**
 * The naive search (talk, section 3.4, footnote 2): for each of the ~2k|T| candidate planes
 * (the clipped bounds of every primitive on every axis), count the primitives on each side by
 * scanning all of them. O(|T|^2) per node: the reference the faster searches must match.
 */
final class NaivePlaneSearch implements PlaneSearch {
    @Override public void search(BuildNode node, SahCost sah, SahSplit best) {
        int n = node.size();
        for (int axis = 0; axis < node.dimension(); axis++) {
            double[] candidates = new double[2 * n];
            for (int j = 0; j < n; j++) {
                candidates[2 * j] = node.clippedMin(j, axis);
                candidates[2 * j + 1] = node.clippedMax(j, axis);
            }
            Arrays.sort(candidates);
            for (int c = 0; c < candidates.length; c++) {
                double x = candidates[c];
                if (c > 0 && candidates[c - 1] == x) continue;
                int nl = 0, nr = 0, np = 0;
                for (int j = 0; j < n; j++) {
                    double lo = node.clippedMin(j, axis), hi = node.clippedMax(j, axis);
                    if (lo == x && hi == x) np++;
                    else {
                        if (lo < x) nl++;
                        if (hi > x) nr++;
                    }
                }
                best.offer(sah, axis, x, nl, np, nr);
            }
        }
    }
}
