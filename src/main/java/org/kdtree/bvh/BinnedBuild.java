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
 * <p>The inner loops run on flat arrays of bounds and centroids with per-task scratch, and
 * allocate nothing per primitive.
 */
final class BinnedBuild {
    /** Nodes of at least this many primitives are built as tasks of their own when threads build. */
    private static final int FORK_ABOVE = 4096;

    private final int k;
    /** Per primitive, k minima then k maxima. */
    private final double[] bounds;
    /** Per primitive, twice its centroid (min + max), k values. */
    private final double[] centre;
    /** The primitive order, partitioned in place: each node owns one stretch of it. */
    private final int[] order;
    private final CostModel cost;
    private final int bins, leafSize, depthCap;
    private final boolean parallel;

    private BinnedBuild(int k, double[] bounds, double[] centre, int[] order, BvhBuilder settings) {
        this.k = k;
        this.bounds = bounds;
        this.centre = centre;
        this.order = order;
        this.cost = settings.costModel();
        this.bins = settings.bins();
        this.leafSize = settings.leafSize();
        this.depthCap = settings.depthCap();
        this.parallel = settings.threads() > 1;
    }

    static Bvh build(Primitives prims, BvhBuilder settings) {
        int k = prims.dimension(), n = prims.size();
        double[] bounds = new double[2 * k * n], centre = new double[k * n];
        int[] order = new int[n];
        Box b = new Box(k);
        int m = 0;
        for (int i = 0; i < n; i++) {
            prims.bounds(i, b);
            if (b.isEmpty()) continue;          // nothing of it can be hit
            for (int a = 0; a < k; a++) {
                double lo = b.min(a), hi = b.max(a);
                bounds[2 * k * i + a] = lo;
                bounds[2 * k * i + k + a] = hi;
                centre[k * i + a] = lo + hi;
            }
            order[m++] = i;
        }
        BinnedBuild run = new BinnedBuild(k, bounds, centre, java.util.Arrays.copyOf(order, m), settings);
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
        final double[] box = new double[2 * k * k * bins];
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

    /** The bounds of the stretch's primitives into {@code box}, and of their centroids. */
    private void enclose(int from, int to, double[] box, double[] cmin, double[] cmax) {
        for (int a = 0; a < k; a++) {
            box[a] = cmin[a] = Double.POSITIVE_INFINITY;
            box[k + a] = cmax[a] = Double.NEGATIVE_INFINITY;
        }
        for (int i = from; i < to; i++) {
            int p = order[i], o = 2 * k * p, c = k * p;
            for (int a = 0; a < k; a++) {
                box[a] = Math.min(box[a], bounds[o + a]);
                box[k + a] = Math.max(box[k + a], bounds[o + k + a]);
                cmin[a] = Math.min(cmin[a], centre[c + a]);
                cmax[a] = Math.max(cmax[a], centre[c + a]);
            }
        }
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
        double area = BoxArea.of(box, 0, k);
        double best = Double.POSITIVE_INFINITY;
        int bestAxis = -1, bestBin = 0;
        for (int a = 0; a < k; a++) {
            if (!(cmax[a] > cmin[a])) continue;
            bin(from, to, a, nb, cmin[a], cmax[a], s);
            double c = sweep(a, nb, s, area);
            if (c < best) {
                best = c;
                bestAxis = a;
                bestBin = s.sweepBin;
            }
        }
        if (bestAxis < 0) return n > leafSize ? median(from, to, cmin, cmax) : -1;
        if (n <= leafSize && best >= cost.ki() * n) return -1;
        double scale = scale(nb, cmin[bestAxis], cmax[bestAxis]);
        return partition(from, to, bestAxis, nb, cmin[bestAxis], scale, bestBin);
    }

    private static int ceilLog2(int n) {
        return n <= 1 ? 0 : 32 - Integer.numberOfLeadingZeros(n - 1);
    }

    private static double scale(int nb, double lo, double hi) {
        return nb / (hi - lo);
    }

    private int binOf(double c, double lo, double scale, int nb) {
        int b = (int) ((c - lo) * scale);
        return b < 0 ? 0 : b >= nb ? nb - 1 : b;
    }

    /** Counts the stretch's centroids into {@code nb} bins on {@code axis} and grows each bin's box. */
    private void bin(int from, int to, int axis, int nb, double lo, double hi, Scratch s) {
        int[] count = s.count;
        double[] box = s.box;
        int cb = axis * bins, bb = 2 * k * axis * bins;
        for (int b = 0; b < nb; b++) {
            count[cb + b] = 0;
            for (int a = 0; a < k; a++) {
                box[bb + 2 * k * b + a] = Double.POSITIVE_INFINITY;
                box[bb + 2 * k * b + k + a] = Double.NEGATIVE_INFINITY;
            }
        }
        double scale = scale(nb, lo, hi);
        for (int i = from; i < to; i++) {
            int p = order[i];
            int b = binOf(centre[k * p + axis], lo, scale, nb);
            count[cb + b]++;
            int o = 2 * k * p, d = bb + 2 * k * b;
            for (int a = 0; a < k; a++) {
                if (bounds[o + a] < box[d + a]) box[d + a] = bounds[o + a];
                if (bounds[o + k + a] > box[d + k + a]) box[d + k + a] = bounds[o + k + a];
            }
        }
    }

    /**
     * The cheapest boundary between bins on {@code axis}: its SAH cost
     * {@code Kt + Ki (A_L N_L + A_R N_R) / A}, the boundary left in the scratch. A node of
     * zero area (all its primitives at one point or on one line in 3-D) weighs each side by its count.
     */
    private double sweep(int axis, int nb, Scratch s, double area) {
        int[] count = s.count;
        double[] box = s.box, acc = s.acc;
        int cb = axis * bins, bb = 2 * k * axis * bins;
        clear(acc);
        int n = 0;
        for (int b = nb - 1; b > 0; b--) {
            grow(acc, box, bb + 2 * k * b);
            n += count[cb + b];
            s.suffixCount[b] = n;
            s.suffixArea[b] = n == 0 ? 0 : BoxArea.of(acc, 0, k);
        }
        clear(acc);
        double best = Double.POSITIVE_INFINITY, norm = area > 0 ? 1 / area : 0;
        n = 0;
        for (int b = 1; b < nb; b++) {
            grow(acc, box, bb + 2 * k * (b - 1));
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

    /** Moves the primitives whose centroid bin on {@code axis} is below {@code bin} first; returns where the rest start. */
    private int partition(int from, int to, int axis, int nb, double lo, double scale, int bin) {
        int i = from, j = to - 1;
        while (true) {
            while (i <= j && binOf(centre[k * order[i] + axis], lo, scale, nb) < bin) i++;
            while (i <= j && binOf(centre[k * order[j] + axis], lo, scale, nb) >= bin) j--;
            if (i >= j) return i;
            int t = order[i];
            order[i] = order[j];
            order[j] = t;
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

    /** Quickselect: puts the primitive of rank {@code nth} (by centroid on {@code axis}) at {@code nth}, smaller before, larger after. */
    private void select(int lo, int hi, int nth, int axis) {
        while (hi > lo) {
            double pivot = median3(centre[k * order[lo] + axis], centre[k * order[(lo + hi) >>> 1] + axis], centre[k * order[hi] + axis]);
            // Three-way partition: < pivot, == pivot, > pivot (many equal centroids stay linear).
            int lt = lo, gt = hi, i = lo;
            while (i <= gt) {
                double c = centre[k * order[i] + axis];
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

    private void swap(int i, int j) {
        int t = order[i];
        order[i] = order[j];
        order[j] = t;
    }
}
