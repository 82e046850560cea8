package org.kdtree.build;

import org.kdtree.geom.Box;
import org.kdtree.geom.SplitPlane;

/**
 * Splits at the middle of the voxel (talk, section 3.2.1): axis {@code n = D(V) mod k},
 * {@code xi = (V_min,n + V_max,n) / 2}. Terminates on {@code |T| <= Kmintri} or
 * {@code D(V) >= Kmaxdepth} (section 3.2.3).
 */
public class MedianPlaneBuilder extends KdTreeBuilder {
    private int minPrimitives = 2;

    @Override public String name() { return "median-plane"; }

    @Override protected boolean terminate(BuildContext context, BuildNode node) {
        return node.size() <= minPrimitives || node.depth() >= context.depthCap();
    }

    @Override protected SplitPlane findPlane(BuildContext context, BuildNode node) {
        int axis = node.depth() % node.dimension();
        Box v = node.voxel();
        return new SplitPlane(axis, 0.5 * (v.min(axis) + v.max(axis)));
    }

    /** Kmintri: a node with at most this many primitives becomes a leaf (default 2). */
    public int minPrimitives() { return minPrimitives; }

    /** Sets Kmintri (>= 0). */
    public MedianPlaneBuilder minPrimitives(int n) {
        if (n < 0) throw new IllegalArgumentException("Kmintri must be >= 0, got " + n);
        this.minPrimitives = n;
        return this;
    }

    @Override public MedianPlaneBuilder maxDepth(int depth) { super.maxDepth(depth); return this; }

    @Override public String describeSettings() { return "Kmintri=" + minPrimitives + " " + super.describeSettings(); }
}
