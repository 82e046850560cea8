package org.kdtree.bvh;

import java.util.concurrent.CancellationException;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.RecursiveTask;
import org.kdtree.geom.Box;
import org.kdtree.shape.Primitives;
import org.kdtree.tree.CostModel;

/**
 * One build of a {@link Bvh}: the top-down binned SAH over the primitives' bounds (Wald 2007).
 * Each node bins its primitives' centroids on every axis, sweeps the bins for the cheapest
 * boundary under the cost model, and partitions its stretch of the primitive order in place; a
 * node that cannot be cut by centroids, or that would go past the depth cap, is cut at its
 * median. Large subtrees are built in parallel; the hierarchy is the same at any thread count.
 *
 * <p>The primitives' bounds are kept in the order being partitioned (a reference per primitive:
 * its k minima, its k maxima, and its index beside), so that each node reads its stretch in
 * sequence, and one pass bins every axis. The inner loops allocate nothing.
 */
final class BinnedBuild {
    /** Nodes of at least this many primitives are built as tasks of their own when threads build. */
    private static final int FORK_ABOVE = 4096;

    private final int k;
    /** Per reference, in partition order: k minima then k maxima; twice a centroid is min + max. */
    private final double[] bounds;
    /** The primitive of each reference, partitioned in place with it: each node owns one stretch. */
    private final int[] order;
    private final CostModel cost;
    private final int bins, leafSize, depthCap;
    private final boolean parallel;

    private BinnedBuild(int k, double[] bounds, int[] order, BvhBuilder settings) {
        this.k = k;
        this.bounds = bounds;
        this.order = order;
        this.cost = settings.costModel();
        this.bins = settings.bins();
        this.leafSize = settings.leafSize();
        this.depthCap = settings.depthCap();
        this.parallel = settings.threads() > 1;
    }

    static Bvh build(Primitives prims, BvhBuilder settings) {
        int k = prims.dimension(), n = prims.size();
        double[] bounds = new double[2 * k * n];
        int[] order = new int[n];
        Box b = new Box(k);
        int m = 0;
        for (int i = 0; i < n; i++) {
            prims.bounds(i, b);
            if (b.isEmpty()) continue;          // nothing of it can be hit
            for (int a = 0; a < k; a++) {
                bounds[2 * k * m + a] = b.min(a);
                bounds[2 * k * m + k + a] = b.max(a);
            }
            order[m++] = i;
        }
        BinnedBuild run = new BinnedBuild(k, bounds, java.util.Arrays.copyOf(order, m), settings);
        BuildNode root;
        if (run.parallel && m >= FORK_ABOVE) {
            ForkJoinPool pool = new ForkJoinPool(settings.threads());
            try {
                root = pool.invoke(run.task(0, m, 0));
            } finally {
                pool.shutdownNow();
            }
        } else {
            root = run.node(0, m, 0, run.new Scratch());
        }
        return Bvh.of(k, root, run.order, settings);
    }

    /** The scratch of one task: bin counts and boxes per axis, the sweep's suffix areas. */
    private final class Scratch {
        final int[] count = new int[k * bins];
        /** Per axis and bin, the bin's box: k minima, k maxima. */
        final double[] box = new double[2 * k * k * bins];
        /** Per axis, bins per unit of (doubled) centroid; 0 where the centroids do not spread. */
        final double[] scale = new double[k];
        final double[] suffixArea = new double[bins];
        final int[] suffixCount = new int[bins];
        final double[] acc = new double[2 * k];
        final double[] cmin = new double[k], cmax = new double[k];
        /** The boundary {@link #sweep} chose last (bins below it go left). */
        int sweepBin;
    }

    private RecursiveTask<BuildNode> task(int from, int to, int depth) {
        return new RecursiveTask<>() {
            @Override protected BuildNode compute() {
                return node(from, to, depth, new Scratch());
            }
        };
    }

    /** The node over {@code order[from, to)}: a leaf, or a split with its two subtrees. */
    BuildNode node(int from, int to, int depth, Scratch s) {
        if (Thread.currentThread().isInterrupted()) throw new CancellationException("BVH build interrupted");
        int n = to - from;
        BuildNode node = new BuildNode(k);
        double[] cmin = s.cmin, cmax = s.cmax;
        enclose(from, to, node.box, cmin, cmax);
        if (n <= 1 || depth >= depthCap) return node.leaf(from, n);
        int mid = split(from, to, depth, node.box, cmin, cmax, s);
        if (mid < 0) return node.leaf(from, n);
        if (parallel && n >= FORK_ABOVE) {
            RecursiveTask<BuildNode> right = task(mid, to, depth + 1);
            right.fork();
            BuildNode left = node(from, mid, depth + 1, s);
            return node.interior(left, right.join());
        }
        BuildNode left = node(from, mid, depth + 1, s);
        return node.interior(left, node(mid, to, depth + 1, s));
    }

    /** The bounds of the stretch's primitives into {@code box}, and of their centroids (doubled). */
    private void enclose(int from, int to, double[] box, double[] cmin, double[] cmax) {
        for (int a = 0; a < k; a++) {
            box[a] = cmin[a] = Double.POSITIVE_INFINITY;
            box[k + a] = cmax[a] = Double.NEGATIVE_INFINITY;
        }
        double[] r = bounds;
        if (k == 3) {
            enclose3(from, to, box, cmin, cmax);
            return;
        }
        for (int o = 2 * k * from, end = 2 * k * to; o < end; o += 2 * k) {
            for (int a = 0; a < k; a++) {
                double lo = r[o + a], hi = r[o + k + a], c = lo + hi;
                if (lo < box[a]) box[a] = lo;
                if (hi > box[k + a]) box[k + a] = hi;
                if (c < cmin[a]) cmin[a] = c;
                if (c > cmax[a]) cmax[a] = c;
            }
        }
    }

    /** {@link #enclose} in 3-D, unrolled, with the running bounds in locals. */
    private void enclose3(int from, int to, double[] box, double[] cmin, double[] cmax) {
        double[] r = bounds;
        double bx0 = box[0], by0 = box[1], bz0 = box[2], bx1 = box[3], by1 = box[4], bz1 = box[5];
        double cx0 = cmin[0], cy0 = cmin[1], cz0 = cmin[2], cx1 = cmax[0], cy1 = cmax[1], cz1 = cmax[2];
        for (int o = 6 * from, end = 6 * to; o < end; o += 6) {
            double x0 = r[o], y0 = r[o + 1], z0 = r[o + 2], x1 = r[o + 3], y1 = r[o + 4], z1 = r[o + 5];
            bx0 = Math.min(bx0, x0); by0 = Math.min(by0, y0); bz0 = Math.min(bz0, z0);
            bx1 = Math.max(bx1, x1); by1 = Math.max(by1, y1); bz1 = Math.max(bz1, z1);
            double cx = x0 + x1, cy = y0 + y1, cz = z0 + z1;
            cx0 = Math.min(cx0, cx); cy0 = Math.min(cy0, cy); cz0 = Math.min(cz0, cz);
            cx1 = Math.max(cx1, cx); cy1 = Math.max(cy1, cy); cz1 = Math.max(cz1, cz);
        }
        box[0] = bx0; box[1] = by0; box[2] = bz0; box[3] = bx1; box[4] = by1; box[5] = bz1;
        cmin[0] = cx0; cmin[1] = cy0; cmin[2] = cz0; cmax[0] = cx1; cmax[1] = cy1; cmax[2] = cz1;
    }

    /**
     * Where the stretch is cut: the partition point of the cheapest binned plane, or of the
     * median, or -1 when a leaf is cheaper and allowed.
     */
    private int split(int from, int to, int depth, double[] box, double[] cmin, double[] cmax, Scratch s) {
        int n = to - from;
        // Past this depth only halving reaches leaves of leafSize before the cap: halve.
        if (depthCap - depth <= ceilLog2((n + leafSize - 1) / leafSize)) return median(from, to, cmin, cmax);
        int nb = Math.min(bins, n);
        bin(from, to, nb, cmin, cmax, s);
        double area = BoxArea.of(box, 0, k);
        double best = Double.POSITIVE_INFINITY;
        int bestAxis = -1, bestBin = 0;
        for (int a = 0; a < k; a++) {
            if (!(cmax[a] > cmin[a])) continue;
            double c = sweep(a, nb, s, area);
            if (c < best) {
                best = c;
                bestAxis = a;
                bestBin = s.sweepBin;
            }
        }
        if (bestAxis < 0) return n > leafSize ? median(from, to, cmin, cmax) : -1;
        if (n <= leafSize && best >= cost.ki() * n) return -1;
        return partition(from, to, bestAxis, nb, cmin[bestAxis], s.scale[bestAxis], bestBin);
    }

    private static int ceilLog2(int n) {
        return n <= 1 ? 0 : 32 - Integer.numberOfLeadingZeros(n - 1);
    }

    /** The bin of a (doubled) centroid coordinate {@code c}: the same expression for binning and partitioning. */
    private static int binOf(double c, double lo, double scale, int nb) {
        int b = (int) ((c - lo) * scale);
        return b < 0 ? 0 : b >= nb ? nb - 1 : b;
    }

    /**
     * One pass over the stretch: counts each reference into its bin on every axis where the
     * centroids spread, and grows that bin's box.
     */
    private void bin(int from, int to, int nb, double[] cmin, double[] cmax, Scratch s) {
        int[] count = s.count;
        double[] box = s.box, scale = s.scale, r = bounds;
        int kk = 2 * k;
        for (int a = 0; a < k; a++) {
            scale[a] = cmax[a] > cmin[a] ? nb / (cmax[a] - cmin[a]) : 0;
            for (int b = 0; b < nb; b++) {
                count[a * bins + b] = 0;
                int d = kk * (a * bins + b);
                for (int x = 0; x < k; x++) {
                    box[d + x] = Double.POSITIVE_INFINITY;
                    box[d + k + x] = Double.NEGATIVE_INFINITY;
                }
            }
        }
        if (k == 3) {
            bin3(from, to, nb, cmin, s);
            return;
        }
        for (int o = kk * from, end = kk * to; o < end; o += kk) {
            for (int a = 0; a < k; a++) {
                if (scale[a] == 0) continue;
                int b = binOf(r[o + a] + r[o + k + a], cmin[a], scale[a], nb);
                count[a * bins + b]++;
                int d = kk * (a * bins + b);
                for (int x = 0; x < kk; x += 1) {
                    double v = r[o + x];
                    if (x < k ? v < box[d + x] : v > box[d + x]) box[d + x] = v;
                }
            }
        }
    }

    /** {@link #bin}'s pass in 3-D, unrolled: the build's hottest loop. */
    private void bin3(int from, int to, int nb, double[] cmin, Scratch s) {
        int[] count = s.count;
        double[] box = s.box, r = bounds;
        double sx = s.scale[0], sy = s.scale[1], sz = s.scale[2], lx = cmin[0], ly = cmin[1], lz = cmin[2];
        int by = bins, bz = 2 * bins;
        for (int o = 6 * from, end = 6 * to; o < end; o += 6) {
            double x0 = r[o], y0 = r[o + 1], z0 = r[o + 2], x1 = r[o + 3], y1 = r[o + 4], z1 = r[o + 5];
            if (sx != 0) grow3(box, count, binOf(x0 + x1, lx, sx, nb), x0, y0, z0, x1, y1, z1);
            if (sy != 0) grow3(box, count, by + binOf(y0 + y1, ly, sy, nb), x0, y0, z0, x1, y1, z1);
            if (sz != 0) grow3(box, count, bz + binOf(z0 + z1, lz, sz, nb), x0, y0, z0, x1, y1, z1);
        }
    }

    private static void grow3(double[] box, int[] count, int b, double x0, double y0, double z0, double x1, double y1, double z1) {
        count[b]++;
        int d = 6 * b;
        box[d] = Math.min(box[d], x0);
        box[d + 1] = Math.min(box[d + 1], y0);
        box[d + 2] = Math.min(box[d + 2], z0);
        box[d + 3] = Math.max(box[d + 3], x1);
        box[d + 4] = Math.max(box[d + 4], y1);
        box[d + 5] = Math.max(box[d + 5], z1);
    }

    /**
     * The cheapest boundary between bins on {@code axis}: its SAH cost
     * {@code Kt + Ki (A_L N_L + A_R N_R) / A}, the boundary left in the scratch. A node of
     * zero area (all its primitives at one point or on one line in 3-D) weighs each side by its count.
     */
    private double sweep(int axis, int nb, Scratch s, double area) {
        int[] count = s.count;
        double[] box = s.box, acc = s.acc;
        int cb = axis * bins, kk = 2 * k;
        clear(acc);
        int n = 0;
        for (int b = nb - 1; b > 0; b--) {
            grow(acc, box, kk * (cb + b));
            n += count[cb + b];
            s.suffixCount[b] = n;
            s.suffixArea[b] = n == 0 ? 0 : BoxArea.of(acc, 0, k);
        }
        clear(acc);
        double best = Double.POSITIVE_INFINITY, norm = area > 0 ? 1 / area : 0;
        n = 0;
        for (int b = 1; b < nb; b++) {
            grow(acc, box, kk * (cb + b - 1));
            n += count[cb + b - 1];
            int right = s.suffixCount[b];
            if (n == 0 || right == 0) continue;
            double c = area > 0 ? cost.kt() + cost.ki() * (BoxArea.of(acc, 0, k) * n + s.suffixArea[b] * right) * norm
                    : cost.kt() + cost.ki() * Math.max(n, right);
            if (c < best) {
                best = c;
                s.sweepBin = b;
            }
        }
        return best;
    }

    private void clear(double[] acc) {
        for (int a = 0; a < k; a++) {
            acc[a] = Double.POSITIVE_INFINITY;
            acc[k + a] = Double.NEGATIVE_INFINITY;
        }
    }

    private void grow(double[] acc, double[] box, int o) {
        for (int a = 0; a < k; a++) {
            if (box[o + a] < acc[a]) acc[a] = box[o + a];
            if (box[o + k + a] > acc[k + a]) acc[k + a] = box[o + k + a];
        }
    }

    /** Twice the centroid of reference {@code i} on {@code axis}. */
    private double centre(int i, int axis) {
        return bounds[2 * k * i + axis] + bounds[2 * k * i + k + axis];
    }

    /** Moves the references whose centroid bin on {@code axis} is below {@code bin} first; returns where the rest start. */
    private int partition(int from, int to, int axis, int nb, double lo, double scale, int bin) {
        int i = from, j = to - 1;
        while (true) {
            while (i <= j && binOf(centre(i, axis), lo, scale, nb) < bin) i++;
            while (i <= j && binOf(centre(j, axis), lo, scale, nb) >= bin) j--;
            if (i >= j) return i;
            swap(i, j);
        }
    }

    /**
     * Halves the stretch at the median centroid on the axis where centroids spread most (or
     * anywhere when they coincide): the cut that keeps any build within the depth cap.
     */
    private int median(int from, int to, double[] cmin, double[] cmax) {
        int mid = (from + to) >>> 1, axis = 0;
        for (int a = 1; a < k; a++) if (cmax[a] - cmin[a] > cmax[axis] - cmin[axis]) axis = a;
        if (cmax[axis] > cmin[axis]) select(from, to - 1, mid, axis);
        return mid;
    }

    /** Quickselect: puts the reference of rank {@code nth} (by centroid on {@code axis}) at {@code nth}, smaller before, larger after. */
    private void select(int lo, int hi, int nth, int axis) {
        while (hi > lo) {
            double pivot = median3(centre(lo, axis), centre((lo + hi) >>> 1, axis), centre(hi, axis));
            // Three-way partition: < pivot, == pivot, > pivot (many equal centroids stay linear).
            int lt = lo, gt = hi, i = lo;
            while (i <= gt) {
                double c = centre(i, axis);
                if (c < pivot) swap(lt++, i++);
                else if (c > pivot) swap(i, gt--);
                else i++;
            }
            if (nth < lt) hi = lt - 1;
            else if (nth > gt) lo = gt + 1;
            else return;
        }
    }

    private static double median3(double a, double b, double c) {
        return Math.max(Math.min(a, b), Math.min(Math.max(a, b), c));
    }

    /** Swaps two references: their bounds and their primitives. */
    private void swap(int i, int j) {
        int t = order[i];
        order[i] = order[j];
        order[j] = t;
        int kk = 2 * k;
        for (int x = 0, a = kk * i, b = kk * j; x < kk; x++) {
            double v = bounds[a + x];
            bounds[a + x] = bounds[b + x];
            bounds[b + x] = v;
        }
    }
}
