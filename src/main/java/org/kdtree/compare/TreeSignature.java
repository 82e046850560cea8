package org.kdtree.compare;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import org.kdtree.kdtree.KdTree;
import org.kdtree.limits.Limits;

/**
 * A kd-tree's structure in a few small arrays, normalised to its root voxel so that translation
 * and uniform scale of the data do not change it (the talk's section 5.2: where the split planes
 * lie, where the large voxels are and where the small ones):
 *
 * <ul>
 * <li>{@link #volumes()}: the share of the root's volume held by leaves of each size, binned by
 *     {@code -log2} of the leaf's fraction of the root (bin i: a leaf 2<sup>-i</sup> of the root);
 * <li>{@link #depths()}: the share of the leaves at each depth, 0 to {@link #DEPTH_BINS} - 1;
 * <li>{@link #splits()}: for each of the first {@link #SPLIT_DEPTHS} levels, the share of that
 *     level's split planes at each position of each axis ({@link #POSITION_BINS} positions across
 *     the root);
 * <li>{@link #occupancy()}: a picture on a common grid over the unit cube the root is scaled
 *     into: each cell holds the depth of the leaves covering it (their mean, by overlap).
 * </ul>
 *
 * <p>The root is centred in the unit cube and scaled by its longest side (uniformly, so a long
 * thin set stays long and thin). The grid has 2<sup>b</sup> cells along each of its first
 * {@link #gridAxes()} axes (at most {@link #MAX_GRID_AXES}) and at most {@link #MAX_CELLS} cells
 * in all: 64 x 64 in 2-D, 16<sup>3</sup> in 3-D, 4<sup>5</sup> in 5-D, 2 per axis from 7-D on;
 * axes beyond the twelfth are projected (a cell holds the mean over them). An axis along which the
 * data is flat is projected too: every cell along it holds the same value.
 *
 * <p>Histograms are filled with linear (tent) weights between the two nearest bins, so a value
 * that moves a little moves the signature a little: rounding in the shifted and scaled copy of a
 * set cannot jump a bin. Immutable; {@link #toBytes()} and {@link #fromBytes(byte[])} keep it in a
 * file.
 */
public final class TreeSignature {
    /** Bins of {@link #volumes()}: leaves down to 2<sup>-63</sup> of the root (smaller ones in the last). */
    public static final int VOLUME_BINS = 64;
    /** Bins of {@link #depths()}: every depth a tree may have. */
    public static final int DEPTH_BINS = (int) Limits.MAX_DEPTH.max() + 1;
    /** Levels whose split planes {@link #splits()} records (the root's level is 0). */
    public static final int SPLIT_DEPTHS = 6;
    /** Positions across the root per axis in {@link #splits()}: bins centred at 0, 1/14, ..., 1. */
    public static final int POSITION_BINS = 15;
    /** The most axes the occupancy grid spans; further axes are projected. */
    public static final int MAX_GRID_AXES = 12;
    /** The most cells of the occupancy grid. */
    public static final int MAX_CELLS = 1 << MAX_GRID_AXES;

    private static final int MAGIC = 0x6b645347;   // "kdSG"
    private static final int VERSION = 1;

    final int dimension;
    final int leaves;
    final int maxDepth;
    final int gridAxes;
    final int cellBits;
    final double[] volumes;
    final double[] depths;
    final double[] splits;
    final double[] occupancy;

    TreeSignature(int dimension, int leaves, int maxDepth, int cellBits, double[] volumes, double[] depths, double[] splits,
                  double[] occupancy) {
        this.dimension = dimension;
        this.leaves = leaves;
        this.maxDepth = maxDepth;
        this.gridAxes = gridAxes(dimension);
        this.cellBits = cellBits;
        this.volumes = volumes;
        this.depths = depths;
        this.splits = splits;
        this.occupancy = occupancy;
    }

    /**
     * {@return the signature of a tree} One walk over the tree, then the occupancy grid: linear in
     * the nodes and the grid's cells.
     *
     * @param tree any kd-tree: over points, 2-D shapes or a mesh, by any builder
     */
    public static TreeSignature of(KdTree tree) {
        return new SignatureWalk(tree).signature();
    }

    /** {@return the number of grid axes for a dimension} */
    static int gridAxes(int dimension) {
        return Math.min(dimension, MAX_GRID_AXES);
    }

    /** {@return the grid's cells per axis, as a power of two, for a dimension} */
    static int cellBits(int dimension) {
        return Math.max(1, MAX_GRID_AXES / gridAxes(dimension));
    }

    /** {@return the dimension of the tree's data} */
    public int dimension() { return dimension; }

    /** {@return the number of leaves of the tree} */
    public int leaves() { return leaves; }

    /** {@return the depth of the deepest leaf} */
    public int maxDepth() { return maxDepth; }

    /** {@return the axes the occupancy grid spans: the first ones, at most {@link #MAX_GRID_AXES}} */
    public int gridAxes() { return gridAxes; }

    /** {@return the occupancy grid's cells per axis} (a power of two) */
    public int cellsPerAxis() { return 1 << cellBits; }

    /** {@return the share of the root's volume per leaf size (bin i: leaves 2<sup>-i</sup> of the root); sums to 1} */
    public double[] volumes() { return volumes.clone(); }

    /** {@return the share of the leaves per depth; sums to 1} */
    public double[] depths() { return depths.clone(); }

    /**
     * {@return the split planes' positions}: index {@code (level * dimension + axis) * POSITION_BINS + bin},
     * each level's shares summing to 1 (0 for a level without splits)
     */
    public double[] splits() { return splits.clone(); }

    /**
     * {@return the occupancy picture}: the leaves' mean depth per cell, cell index
     * {@code sum over grid axes a of (cell along a) << (a * bits)}, axis 0 varying fastest
     */
    public double[] occupancy() { return occupancy.clone(); }

    /** {@return the signature as bytes, for a cache file} */
    public byte[] toBytes() {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream(8 * (volumes.length + depths.length + splits.length + occupancy.length) + 64);
        try (DataOutputStream out = new DataOutputStream(bytes)) {
            for (int v : new int[] {MAGIC, VERSION, dimension, leaves, maxDepth, cellBits}) out.writeInt(v);
            for (double[] a : new double[][] {volumes, depths, splits, occupancy}) {
                out.writeInt(a.length);
                for (double v : a) out.writeDouble(v);
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);   // a byte array does not fail
        }
        return bytes.toByteArray();
    }

    /**
     * {@return the signature {@link #toBytes()} wrote}
     *
     * @param bytes what {@link #toBytes()} returned
     * @throws IllegalArgumentException if the bytes are not such a signature (another version, cut short)
     */
    public static TreeSignature fromBytes(byte[] bytes) {
        try (DataInputStream in = new DataInputStream(new ByteArrayInputStream(bytes))) {
            if (in.readInt() != MAGIC || in.readInt() != VERSION) throw new IllegalArgumentException("not a tree signature of this version");
            int dimension = in.readInt(), leaves = in.readInt(), maxDepth = in.readInt(), cellBits = in.readInt();
            if (dimension < 1 || dimension > Limits.DIMENSION.max() || cellBits != cellBits(dimension) || leaves < 1
                    || maxDepth < 0 || maxDepth >= DEPTH_BINS)
                throw new IllegalArgumentException("a tree signature of an impossible shape");
            double[] volumes = read(in, VOLUME_BINS), depths = read(in, DEPTH_BINS),
                    splits = read(in, SPLIT_DEPTHS * dimension * POSITION_BINS), occupancy = read(in, 1 << (cellBits * gridAxes(dimension)));
            if (in.read() >= 0) throw new IllegalArgumentException("a tree signature followed by more bytes");
            return new TreeSignature(dimension, leaves, maxDepth, cellBits, volumes, depths, splits, occupancy);
        } catch (IOException e) {
            throw new IllegalArgumentException("a tree signature cut short", e);
        }
    }

    private static double[] read(DataInputStream in, int length) throws IOException {
        if (in.readInt() != length) throw new IllegalArgumentException("a tree signature of an impossible shape");
        double[] a = new double[length];
        for (int i = 0; i < length; i++) {
            a[i] = in.readDouble();
            if (!(a[i] >= 0 && a[i] < Double.POSITIVE_INFINITY)) throw new IllegalArgumentException("a tree signature with a value out of range");
        }
        return a;
    }
}
