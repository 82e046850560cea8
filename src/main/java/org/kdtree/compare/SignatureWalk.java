package org.kdtree.compare;

import org.kdtree.geom.Box;
import org.kdtree.kdtree.KdTree;
import org.kdtree.kdtree.TreeVisitor;

/**
 * One walk over a tree that fills a {@link TreeSignature}'s arrays: every interior node of the
 * first levels adds its split position, every leaf its volume, depth and grid cells.
 */
final class SignatureWalk implements TreeVisitor {
    private final int k;
    private final double[] rootMin, rootExtent;
    private final double[] volumes = new double[TreeSignature.VOLUME_BINS];
    private final double[] depths = new double[TreeSignature.DEPTH_BINS];
    private final double[] splits;
    private final OccupancyGrid grid;
    private final RootFrame frame;
    private int leaves, maxDepth;

    SignatureWalk(KdTree tree) {
        Box root = tree.bounds();
        k = root.dimension();
        rootMin = root.minCorner();
        rootExtent = new double[k];
        for (int a = 0; a < k; a++) rootExtent[a] = root.extent(a);
        splits = new double[TreeSignature.SPLIT_DEPTHS * k * TreeSignature.POSITION_BINS];
        grid = new OccupancyGrid(root);
        frame = new RootFrame(root);
        tree.walk(this);
    }

    TreeSignature signature() {
        scale(depths, 1.0 / Math.max(1, leaves));
        int block = k * TreeSignature.POSITION_BINS;
        for (int level = 0; level < TreeSignature.SPLIT_DEPTHS; level++) {
            double sum = 0;
            for (int i = level * block; i < (level + 1) * block; i++) sum += splits[i];
            if (sum > 0) for (int i = level * block; i < (level + 1) * block; i++) splits[i] /= sum;
        }
        return new TreeSignature(k, leaves, maxDepth, TreeSignature.cellBits(k), volumes, depths, splits, grid.cells());
    }

    @Override public void interior(int node, int depth, Box voxel, int axis, double split) {
        if (depth >= TreeSignature.SPLIT_DEPTHS) return;
        double position = rootExtent[axis] > 0 ? (split - rootMin[axis]) / rootExtent[axis] : 0.5;
        int offset = (depth * k + axis) * TreeSignature.POSITION_BINS;
        Histograms.addTent(splits, offset, TreeSignature.POSITION_BINS, position * (TreeSignature.POSITION_BINS - 1), 1);
    }

    @Override public void leaf(int node, int depth, Box voxel, int from, int to) {
        leaves++;
        maxDepth = Math.max(maxDepth, depth);
        depths[Math.min(depth, depths.length - 1)]++;
        double lnFraction = 0, fraction = 1;
        for (int a = 0; a < k; a++) {
            if (frame.flat(a)) continue;   // a flat axis: every leaf spans all of it
            double f = frame.share(a, voxel.extent(a));
            fraction *= f;
            lnFraction += f > 0 ? Math.log(f) : Double.NEGATIVE_INFINITY;
        }
        double bin = -lnFraction / Math.log(2);
        Histograms.addTent(volumes, 0, volumes.length, Math.min(bin, volumes.length - 1), fraction);
        grid.add(voxel, depth);
    }

    private static void scale(double[] a, double factor) {
        for (int i = 0; i < a.length; i++) a[i] *= factor;
    }
}
