package org.kdtree.kdtree;

import org.kdtree.geom.Box;
import org.kdtree.geom.SplitPlane;

/**
 * Splits at the middle of the voxel (talk, section 3.2.1): axis {@code n = D(V) mod k},
 * {@code xi = (V_min,n + V_max,n) / 2}. Terminates on {@code |T| <= Kmintri} or
 * {@code D(V) >= Kmaxdepth} (section 3.2.3).
 */
public class MedianPlaneBuilder extends CyclingAxisBuilder {
    @Override public String name() { return "median-plane"; }

    @Override protected SplitPlane findPlane(BuildContext context, BuildNode node) {
        int axis = axis(node);
        Box v = node.voxel();
        return new SplitPlane(axis, 0.5 * (v.min(axis) + v.max(axis)));
    }
}
