package org.kdtree.kdtree;

import java.util.ArrayList;
import java.util.List;
import org.kdtree.accel.Setting;
import org.kdtree.accel.SharedSettings;
import org.kdtree.geom.Box;
import org.kdtree.geom.SplitPlane;

/**
 * The sliding midpoint rule of Maneewongvatana and Mount ("It's okay to be skinny, if your
 * friends are fat", 1999), the builder for point queries (docs/points.md).
 *
 * <p>Each node is cut across the longest side of its voxel, at the middle of that side, as the
 * median plane would. When every primitive's centre lies on one side of that plane, the plane
 * slides to the nearest centre, so that one child is never empty: the tree has at most one leaf
 * per {@code leafSize / 2} points or so, while cells stay fat where the points are and long and
 * thin only where they are not, which is what the nearest-neighbour search's pruning needs.
 *
 * <p>Only axes on which the centres differ are candidates; a node whose centres all coincide
 * (copies of one point) is a leaf, whatever its size, so duplicate-heavy data builds a small
 * tree quickly. Other primitives are handled through the centres of their clipped bounds, so
 * the builder honours the contract on any scene, but it chooses its planes for points.
 */
public class SlidingMidpointBuilder extends KdTreeBuilder {
    /**
     * The kd-tree builders' rows and the largest leaf ({@link SharedSettings#LEAF_SIZE}); its default, 16,
     * is chosen for memory: the tree over uniformly random points then costs under 8 bytes per point
     * beyond the points themselves (a reference and a share of the nodes), which a test checks on a
     * million 3-D points.
     */
    private static final List<Setting<?>> ROWS = rows();

    private static List<Setting<?>> rows() {
        List<Setting<?>> rows = new ArrayList<>(KdTreeBuilder.ROWS);
        rows.add(SharedSettings.LEAF_SIZE);
        return List.copyOf(rows);
    }

    @Override public String name() { return "sliding-midpoint"; }

    /** {@return the largest number of primitives a leaf holds} unless they coincide or the depth cap is reached. */
    public int leafSize() { return settings().get(SharedSettings.LEAF_SIZE); }

    /**
     * Sets the leaf size (1 .. 65,536).
     *
     * @param n the leaf size
     * @return this builder
     */
    public SlidingMidpointBuilder leafSize(int n) {
        with(SharedSettings.LEAF_SIZE, n);
        return this;
    }

    /** {@return the kd-tree builders' rows and the leaf size} */
    @Override public List<Setting<?>> settingRows() { return ROWS; }

    @Override protected boolean terminate(BuildContext context, BuildNode node) {
        if (node.size() <= leafSize() || node.depth() >= context.depthCap()) return true;
        SplitPlane plane = slidingMidpoint(node);
        if (plane == null) return true; // every centre coincides: no plane separates them
        node.keepPlane(plane);
        return false;
    }

    @Override protected SplitPlane findPlane(BuildContext context, BuildNode node) {
        SplitPlane kept = node.keptPlane();
        return kept != null ? kept : slidingMidpoint(node);
    }

    /** The sliding midpoint plane of the node, or null when all centres coincide. */
    static SplitPlane slidingMidpoint(BuildNode node) {
        int k = node.dimension();
        double[] range = node.scratch(2 * k);   // the centres' minima, then maxima
        centreRange(node, range, k);
        int axis = longestSplittableSide(node.voxel(), range, k);
        if (axis < 0) return null;
        Box v = node.voxel();
        double mid = 0.5 * (v.min(axis) + v.max(axis)), lo = range[axis], hi = range[k + axis];
        // Slide to the nearest centre; the centres lying in the plane go to the side that would
        // otherwise be empty, so both children get at least one.
        if (mid <= lo) return new SplitPlane(axis, lo, true);
        if (mid >= hi) return new SplitPlane(axis, hi, false);
        return new SplitPlane(axis, mid, true);
    }

    /** The range of the primitives' centres (the points themselves, for points) on every axis: minima, then maxima. */
    private static void centreRange(BuildNode node, double[] range, int k) {
        java.util.Arrays.fill(range, 0, k, Double.POSITIVE_INFINITY);
        java.util.Arrays.fill(range, k, 2 * k, Double.NEGATIVE_INFINITY);
        for (int j = 0; j < node.size(); j++) {
            for (int a = 0; a < k; a++) {
                double c = 0.5 * (node.clippedMin(j, a) + node.clippedMax(j, a));
                if (c < range[a]) range[a] = c;
                if (c > range[k + a]) range[k + a] = c;
            }
        }
    }

    /** The axis of the voxel's longest side among those the centres spread over, or -1. */
    private static int longestSplittableSide(Box voxel, double[] range, int k) {
        int best = -1;
        double bestExtent = -1, bestSpread = -1;
        for (int a = 0; a < k; a++) {
            double spread = range[k + a] - range[a], extent = voxel.extent(a);
            if (!(spread > 0)) continue;
            if (extent > bestExtent || (extent == bestExtent && spread > bestSpread)) {
                best = a;
                bestExtent = extent;
                bestSpread = spread;
            }
        }
        return best;
    }


    @Override public String describeSettings() {
        return "leafSize=" + leafSize() + " " + super.describeSettings();
    }
}
