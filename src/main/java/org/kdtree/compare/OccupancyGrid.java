package org.kdtree.compare;

import org.kdtree.geom.Box;

/**
 * The common grid of {@link TreeSignature#occupancy()}: the root voxel centred in the unit cube
 * and scaled by its longest side, 2<sup>bits</sup> cells along each grid axis. Each leaf adds its
 * depth to the cells it overlaps, times the share of the cell it covers (and, for a projected
 * axis, the share of the root's extent it spans), so a cell inside one leaf holds that leaf's
 * depth and a cell cut by several the mean of theirs. Cells (or parts) outside the root hold 0.
 */
final class OccupancyGrid {
    private final int k, axes, cells;
    private final RootFrame frame;
    private final double[] values;
    /** Per grid axis: the first cell a leaf overlaps, how many, and the share of each it covers. */
    private final int[] first, count;
    private final double[][] share;
    private final int[] at;

    OccupancyGrid(Box root) {
        k = root.dimension();
        axes = TreeSignature.gridAxes(k);
        int bits = TreeSignature.cellBits(k);
        cells = 1 << bits;
        frame = new RootFrame(root);
        values = new double[1 << (bits * axes)];
        first = new int[axes];
        count = new int[axes];
        share = new double[axes][cells];
        at = new int[axes];
    }

    /** Adds a leaf's depth to the cells its voxel overlaps. */
    void add(Box voxel, int depth) {
        double weight = depth;
        for (int a = axes; a < k; a++) weight *= frame.share(a, voxel.extent(a));
        for (int a = 0; a < axes; a++) if (!overlap(a, voxel)) return;
        if (weight == 0) return;
        java.util.Arrays.fill(at, 0);
        while (true) {
            int cell = 0;
            double w = weight;
            for (int a = axes - 1; a >= 0; a--) {
                cell = cell * cells + first[a] + at[a];
                w *= share[a][at[a]];
            }
            values[cell] += w;
            int a = 0;
            while (a < axes && ++at[a] == count[a]) at[a++] = 0;
            if (a == axes) return;
        }
    }

    /** The cells the voxel overlaps along grid axis {@code a} and the share of each; false if none. */
    private boolean overlap(int a, Box voxel) {
        double lo, hi;
        if (!frame.flat(a)) {
            lo = frame.toUnit(a, voxel.min(a)) * cells;
            hi = frame.toUnit(a, voxel.max(a)) * cells;
        } else {   // a flat axis is projected: every leaf spans all of it
            lo = 0;
            hi = cells;
        }
        int i0 = Math.max(0, (int) Math.floor(lo)), i1 = Math.min(cells - 1, (int) Math.ceil(hi) - 1);
        if (i1 < i0) return false;
        first[a] = i0;
        count[a] = i1 - i0 + 1;
        for (int i = i0; i <= i1; i++) share[a][i - i0] = Math.max(0, Math.min(hi, i + 1) - Math.max(lo, i));
        return true;
    }

    /** {@return the cells' values} (the grid's own array: call once, at the end) */
    double[] cells() {
        return values;
    }
}
