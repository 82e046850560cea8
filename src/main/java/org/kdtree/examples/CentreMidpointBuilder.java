package org.kdtree.examples;

import org.kdtree.geom.SplitPlane;
import org.kdtree.kdtree.BuildContext;
import org.kdtree.kdtree.BuildNode;
import org.kdtree.kdtree.KdTreeBuilder;

/**
 * The worked example of docs/write-your-own-builder.md: a student's builder in one small class.
 *
 * <p>Like the median-plane builder it cycles the axes ({@code n = D(V) mod k}), but it cuts
 * at the spatial median of the objects' centres, the middle of the range the centres span,
 * rather than the middle of the voxel. Empty space at the voxel's edges therefore no longer
 * attracts the plane. It stops at two objects or at the depth cap.
 */
public class CentreMidpointBuilder extends KdTreeBuilder {
    private static final int MAX_LEAF_SIZE = 2;

    @Override public String name() { return "centre-midpoint"; }

    @Override protected boolean terminate(BuildContext context, BuildNode node) {
        return node.size() <= MAX_LEAF_SIZE || node.depth() >= context.depthCap();
    }

    @Override protected SplitPlane findPlane(BuildContext context, BuildNode node) {
        int axis = node.depth() % node.dimension();
        double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
        for (int j = 0; j < node.size(); j++) {
            double centre = 0.5 * (node.clippedMin(j, axis) + node.clippedMax(j, axis));
            lo = Math.min(lo, centre);
            hi = Math.max(hi, centre);
        }
        return new SplitPlane(axis, 0.5 * (lo + hi));
    }
}
