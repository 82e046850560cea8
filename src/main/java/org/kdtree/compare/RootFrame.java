package org.kdtree.compare;

import org.kdtree.geom.Box;

/**
 * The unit cube a tree's root voxel is drawn into for comparing: centred, scaled by its longest
 * side (uniformly, so a long thin root stays long and thin). The frame of
 * {@link TreeSignature#occupancy()} and of any picture that lays two trees' voxels over each other.
 */
public final class RootFrame {
    private final double[] centre, extent;
    private final double scale;

    /**
     * The frame of a root voxel.
     *
     * @param root the tree's root voxel (its bounds)
     */
    public RootFrame(Box root) {
        int k = root.dimension();
        centre = new double[k];
        extent = new double[k];
        double longest = 0;
        for (int a = 0; a < k; a++) {
            centre[a] = (root.min(a) + root.max(a)) / 2;
            extent[a] = root.extent(a);
            longest = Math.max(longest, extent[a]);
        }
        scale = longest > 0 ? 1 / longest : 1;
    }

    /**
     * {@return a coordinate in the unit cube}
     *
     * @param axis the axis
     * @param x    a coordinate along it, in the data's units
     */
    public double toUnit(int axis, double x) {
        return (x - centre[axis]) * scale + 0.5;
    }

    /**
     * {@return whether the root has no extent along an axis} (the data is flat there)
     *
     * @param axis the axis
     */
    public boolean flat(int axis) {
        return !(extent[axis] > 0);
    }

    /**
     * {@return the share of the root's extent along an axis that an interval spans} (1 along a flat axis)
     *
     * @param axis the axis
     * @param size the interval's length, in the data's units
     */
    public double share(int axis, double size) {
        return flat(axis) ? 1 : size / extent[axis];
    }
}
