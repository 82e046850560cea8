package org.kdtree.kdtree;

import java.util.Arrays;
import org.kdtree.geom.SplitPlane;

/**
 * Splits at the median object (talk, section 3.2.2): axis {@code n = D(V) mod k}; the plane
 * passes through the centre, on that axis, of the median object when the objects are sorted
 * by their centres (the lower median, so that two objects are separated). Each child then
 * holds half the objects, plus or minus the median one. Terminates like {@link MedianPlaneBuilder}.
 */
public class ObjectMedianBuilder extends CyclingAxisBuilder {
    @Override public String name() { return "object-median"; }

    @Override protected SplitPlane findPlane(BuildContext context, BuildNode node) {
        int axis = axis(node);
        int n = node.size();
        double[] centres = node.scratch(n);
        for (int j = 0; j < n; j++) centres[j] = 0.5 * (node.clippedMin(j, axis) + node.clippedMax(j, axis));
        Arrays.sort(centres, 0, n);
        return new SplitPlane(axis, centres[(n - 1) / 2]);
    }
}
