package org.kdtree.build;

import java.util.Arrays;
import org.kdtree.geom.SplitPlane;

/**
 * Splits at the median object (talk, section 3.2.2): axis {@code n = D(V) mod k}; the plane
 * passes through the centre, on that axis, of the median object when the objects are sorted
 * by their centres (the lower median, so that two objects are separated). Each child then
 * holds half the objects, plus or minus the median one. Terminates like {@link MedianPlaneBuilder}.
 */
public class ObjectMedianBuilder extends KdTreeBuilder {
    private int minPrimitives = 2;

    @Override public String name() { return "object-median"; }

    @Override protected boolean terminate(BuildContext context, BuildNode node) {
        return node.size() <= minPrimitives || node.depth() >= context.depthCap();
    }

    @Override protected SplitPlane findPlane(BuildContext context, BuildNode node) {
        int axis = node.depth() % node.dimension();
        int n = node.size();
        double[] centres = new double[n];
        for (int j = 0; j < n; j++) centres[j] = 0.5 * (node.clippedMin(j, axis) + node.clippedMax(j, axis));
        Arrays.sort(centres);
        return new SplitPlane(axis, centres[(n - 1) / 2]);
    }

    /** Kmintri: a node with at most this many primitives becomes a leaf (default 2). */
    public int minPrimitives() { return minPrimitives; }

    /** Sets Kmintri (>= 0). */
    public ObjectMedianBuilder minPrimitives(int n) {
        if (n < 0) throw new IllegalArgumentException("Kmintri must be >= 0, got " + n);
        this.minPrimitives = n;
        return this;
    }

    @Override public ObjectMedianBuilder maxDepth(int depth) { super.maxDepth(depth); return this; }

    @Override public String describeSettings() { return "Kmintri=" + minPrimitives + " " + super.describeSettings(); }
}
