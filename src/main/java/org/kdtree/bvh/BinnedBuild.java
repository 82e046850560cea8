package org.kdtree.bvh;

import java.util.Arrays;
import java.util.concurrent.CancellationException;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.ForkJoinTask;
import org.kdtree.accel.CostModel;
import org.kdtree.geom.Box;
import org.kdtree.shape.Primitives;

/**
 * One build of a {@link Bvh}: the top-down binned SAH over the primitives' bounds (Wald 2007).
 * Each node bins its primitives' centroids on every axis, sweeps the bins for the cheapest
 * boundary under the cost model, and partitions its stretch of the primitive order in place; a
 * node that cannot be cut by centroids, or that would go past the depth cap, is cut at its
 * median. Large subtrees are built in parallel; the hierarchy is the same at any thread count.
 *
 * <p>The primitives' bounds are kept in the order being partitioned, so that each node reads its
 * stretch in sequence and one pass bins every axis; as floats rounded outwards, so that a box
 * only grows (no primitive is lost) and a pass moves half the bytes doubles would. The inner
 * loops allocate nothing.
 */
final class BinnedBuild {
    /** Nodes of at least this many primitives are built as tasks of their own when threads build. */
    private static final int FORK_ABOVE = 4096;
    /** Nodes of at most this many references are binned on their widest axis only: nine nodes in ten; a fifth faster, 1 % costlier (docs/bvh.md). */
    private static final int SMALL_NODE = 32;
    /**
     * Primitives a leaf tests together, priced as one test ({@code ceil(n / 4)} tests), as Embree
     * prices its four-triangle leaves: nodes below five are not split to save a fraction of a
     * test, and the node count falls towards Embree's (docs/bvh.md).
     */
    private static final int LEAF_BLOCK = 4;

    private final int k;
    /** Per reference, in partition order: k minima then k maxima, rounded outwards ({@link WideNodes#down}); twice a centroid is min + max. */
    private final float[] bounds;
    /** The primitive of each reference, partitioned in place with it: each node owns one stretch. */
    private final int[] order;
    private final CostModel cost;
    private final int bins, leafSize, depthCap;
    private final boolean parallel;

    private BinnedBuild(int k, float[] bounds, int[] order, BvhBuilder settings) {
        this.k = k;
        this.bounds = bounds;
        this.order = order;
        this.cost = settings.costModel();
        this.bins = settings.bins();
        this.leafSize = settings.leafSize();
        this.depthCap = settings.depthCap(0);
        this.parallel = settings.threads() > 1;
    }

    static Bvh build(Primitives prims, BvhBuilder settings) {
        int k = prims.dimension(), n = prims.size();
        float[] bounds = new float[2 * k * n];
        int[] order = new int[n];
        Box b = new Box(k);
        int m = 0;
        for (int i = 0; i < n; i++) {
            prims.bounds(i, b);
            if (b.isEmpty()) continue;          // nothing of it can be hit
            for (int a = 0; a < k; a++) {
                bounds[2 * k * m + a] = WideNodes.down(b.min(a));   // rounded outwards: a box never shrinks
                bounds[2 * k * m + k + a] = WideNodes.up(b.max(a));
            }
            order[m++] = i;
        }
        BinnedBuild run = new BinnedBuild(k, bounds, Arrays.copyOf(order, m), settings);
        BuildNode root = new BuildNode(k);
        run.enclose(0, m, root);
        if (run.parallel && m >= FORK_ABOVE) {
            ForkJoinPool pool = new ForkJoinPool(settings.threads());
            try {
                pool.invoke(run.task(root, 0, m, 0));
            } finally {
                pool.shutdownNow();
            }
        } else {
            run.node(root, 0, m, 0, run.new Scratch());
        }
        return Bvh.of(prims, root, run.order, settings);
    }

    /** The scratch of one task: bin counts and boxes per axis, the sweep's running areas. */
    private final class Scratch {
        final int[] count = new int[k * bins];
        /** Per axis and bin, the bin's box: k minima, k maxima. */
        final double[] box = new double[2 * k * k * bins];
        /** Per axis, bins per unit of (doubled) centroid; 0 where the centroids do not spread. */
        final double[] scale = new double[k];
        /** Per bin, the references and area of the bins up to it (prefix) and from it on (suffix). */
        final double[] prefixArea = new double[bins], suffixArea = new double[bins];
        final int[] prefixCount = new int[bins], suffixCount = new int[bins];
        final double[] acc = new double[2 * k];
        /** The boundary {@link #sweep} chose last (bins below it go left). */
        int sweepBin;
    }

    private ForkJoinTask<BuildNode> task(BuildNode node, int from, int to, int depth) {
        return ForkJoinTask.adapt(() -> node(node, from, to, depth, new Scratch()));
    }

    /** Makes {@code node}, over {@code order[from, to)}, whose box and centroid bounds its parent's cut set, a leaf or a split. */
    private BuildNode node(BuildNode node, int from, int to, int depth, Scratch s) {
        if (Thread.currentThread().isInterrupted()) throw new CancellationException("BVH build interrupted");
        int n = to - from;
        double[] centroids = node.centroids;
        node.centroids = null;                  // needed no more: let it go
        if (n <= 1 || depth >= depthCap) return node.leaf(from, n);
        BuildNode left = new BuildNode(k), right = new BuildNode(k);
        int mid = split(from, to, depth, node.box, centroids, left, right, s);
        if (mid < 0) return node.leaf(from, n);
        ForkJoinTask<BuildNode> forked = parallel && n >= FORK_ABOVE ? task(right, mid, to, depth + 1).fork() : null;
        node(left, from, mid, depth + 1, s);
        if (forked != null) forked.join();
        else node(right, mid, to, depth + 1, s);
        return node.interior(left, right);      // after the subtrees, which it counts
    }

    /** Sets {@code node}'s box to the bounds of the stretch's primitives, and its centroids' bounds (doubled). */
    private void enclose(int from, int to, BuildNode node) {
        double[] box = node.box, c = node.centroids = new double[2 * k];
        clear(box, 0);
        clear(c, 0);
        for (int i = from; i < to; i++) {
            include(box, 0, i);
            growCentroids(c, i);
        }
    }

    /** Grows the box at {@code d} of {@code box} by reference {@code i}'s bounds. */
    private void include(double[] box, int d, int i) {
        for (int a = 0, o = 2 * k * i; a < k; a++) {
            if (bounds[o + a] < box[d + a]) box[d + a] = bounds[o + a];
            if (bounds[o + k + a] > box[d + k + a]) box[d + k + a] = bounds[o + k + a];
        }
    }

    /**
     * Where the stretch is cut: the partition point of the cheapest binned plane, or of the
     * median, or -1 when a leaf is cheaper and allowed. Sets the two children's boxes and centroid bounds.
     */
    private int split(int from, int to, int depth, double[] box, double[] c, BuildNode left, BuildNode right, Scratch s) {
        int n = to - from;
        // Past this depth only halving reaches leaves of leafSize before the cap: halve.
        if (depthCap - depth > ceilLog2((n + leafSize - 1) / leafSize)) {
            int nb = Math.min(bins, Math.max(4, n / 2));   // fewer bins in small nodes: about two references a bin
            bin(from, to, nb, c, s);
            double area = BoxArea.of(box, 0, k), best = Double.POSITIVE_INFINITY;
            int axis = -1, boundary = 0;
            for (int a = 0; a < k; a++) {
                double cost = s.scale[a] == 0 ? Double.POSITIVE_INFINITY : sweep(a, nb, s, area);
                if (cost < best) {
                    best = cost;
                    axis = a;
                    boundary = s.sweepBin;
                }
            }
            if (axis >= 0) {
                if (n <= leafSize && best >= this.cost.ki() * blocks(n)) return -1;
                binBoxes(axis, 0, boundary, s, left.box);
                binBoxes(axis, boundary, nb, s, right.box);
                return partition(from, to, axis, nb, c[axis], s.scale[axis], boundary, left, right);
            }
            if (n <= leafSize) return -1;
        }
        int mid = median(from, to, c);
        enclose(from, mid, left);
        enclose(mid, to, right);
        return mid;
    }

    /** {@return the tests a leaf of {@code n} primitives costs: n in blocks of {@link #LEAF_BLOCK}} */
    private static int blocks(int n) {
        return (n + LEAF_BLOCK - 1) / LEAF_BLOCK;
    }

    private static int ceilLog2(int n) {
        return n <= 1 ? 0 : 32 - Integer.numberOfLeadingZeros(n - 1);
    }

    /** The bin of a (doubled) centroid coordinate {@code c}: the same expression for binning and partitioning. */
    private static int binOf(double c, double lo, double scale, int nb) {
        int b = (int) ((c - lo) * scale);
        return b < 0 ? 0 : b >= nb ? nb - 1 : b;
    }

    /** One pass over the stretch: counts each reference into its bin on every axis where the centroids spread, and grows that bin's box. */
    private void bin(int from, int to, int nb, double[] c, Scratch s) {
        int[] count = s.count;
        double[] box = s.box, scale = s.scale;
        int widest = widest(c);
        for (int a = 0; a < k; a++) {
            scale[a] = c[k + a] > c[a] && (to - from > SMALL_NODE || a == widest) ? nb / (c[k + a] - c[a]) : 0;
            for (int b = a * bins, end = b + nb; b < end; b++) {
                count[b] = 0;
                clear(box, 2 * k * b);
            }
        }
        if (k == 3) {
            bin3(from, to, nb, c, s);
            return;
        }
        for (int i = from; i < to; i++) {
            for (int a = 0; a < k; a++) {
                if (scale[a] == 0) continue;
                int b = a * bins + binOf(centre(i, a), c[a], scale[a], nb);
                count[b]++;
                include(box, 2 * k * b, i);
            }
        }
    }

    /** {@link #bin}'s pass in 3-D, unrolled: the build's hottest loop. */
    private void bin3(int from, int to, int nb, double[] c, Scratch s) {
        int[] count = s.count;
        double[] box = s.box;
        float[] r = bounds;
        double sx = s.scale[0], sy = s.scale[1], sz = s.scale[2], lx = c[0], ly = c[1], lz = c[2];
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
        int cb = axis * bins;
        if (k == 3 && area > 0) {
            // Half areas on both sides: the ratio to the node's is the same.
            accumulate3(s, cb, nb - 1, 1, -1, s.suffixArea, s.suffixCount);
            accumulate3(s, cb, 0, nb - 2, 1, s.prefixArea, s.prefixCount);
            return cheapest(nb, s, 1, cost.ki() * 2 / area);
        }
        accumulate(s, cb, nb - 1, 1, -1, s.suffixArea, s.suffixCount);
        accumulate(s, cb, 0, nb - 2, 1, s.prefixArea, s.prefixCount);
        return cheapest(nb, s, cost.ki(), area > 0 ? 1 / area : 0);
    }

    /**
     * Grows a box over the bins of one axis (those from {@code cb}) from bin {@code b} to bin
     * {@code last} by {@code step}, noting at each bin the references and the area so far.
     */
    private void accumulate(Scratch s, int cb, int b, int last, int step, double[] area, int[] count) {
        double[] acc = s.acc;
        clear(acc, 0);
        for (int n = 0; ; b += step) {
            grow(acc, s.box, 2 * k * (cb + b));
            count[b] = n += s.count[cb + b];
            area[b] = BoxArea.of(acc, 0, k);
            if (b == last) return;
        }
    }

    /** {@link #accumulate} in 3-D, with the running box in locals, noting half areas. */
    private void accumulate3(Scratch s, int cb, int b, int last, int step, double[] area, int[] count) {
        double[] box = s.box;
        double x0 = Double.POSITIVE_INFINITY, y0 = x0, z0 = x0, x1 = Double.NEGATIVE_INFINITY, y1 = x1, z1 = x1;
        for (int n = 0; ; b += step) {
            int d = 6 * (cb + b);
            x0 = Math.min(x0, box[d]); y0 = Math.min(y0, box[d + 1]); z0 = Math.min(z0, box[d + 2]);
            x1 = Math.max(x1, box[d + 3]); y1 = Math.max(y1, box[d + 4]); z1 = Math.max(z1, box[d + 5]);
            count[b] = n += s.count[cb + b];
            double dx = x1 - x0, dy = y1 - y0, dz = z1 - z0;
            area[b] = dx * dy + dy * dz + dz * dx;
            if (b == last) return;
        }
    }

    /**
     * The cheapest boundary b (bins below it left) for the areas {@link #sweep} accumulated:
     * {@code Kt + ki (A_L N_L + A_R N_R) norm}, or by counts alone where {@code norm} is 0.
     */
    private double cheapest(int nb, Scratch s, double ki, double norm) {
        double best = Double.POSITIVE_INFINITY, kt = cost.kt();
        for (int b = 1; b < nb; b++) {
            int left = s.prefixCount[b - 1], right = s.suffixCount[b];
            if (left == 0 || right == 0) continue;
            double c = norm > 0 ? kt + ki * (s.prefixArea[b - 1] * blocks(left) + s.suffixArea[b] * blocks(right)) * norm
                    : kt + cost.ki() * blocks(Math.max(left, right));
            if (c < best) {
                best = c;
                s.sweepBin = b;
            }
        }
        return best;
    }

    /** Empties the box at {@code o} of {@code box} (k minima, k maxima): any point grows it. */
    private void clear(double[] box, int o) {
        for (int a = 0; a < k; a++) {
            box[o + a] = Double.POSITIVE_INFINITY;
            box[o + k + a] = Double.NEGATIVE_INFINITY;
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
        return (double) bounds[2 * k * i + axis] + bounds[2 * k * i + k + axis];
    }

    /** The union of the boxes of bins {@code [from, to)} on {@code axis}: a child's exact box, since each bin's box is its references'. */
    private void binBoxes(int axis, int from, int to, Scratch s, double[] box) {
        clear(box, 0);
        for (int b = axis * bins + from, end = axis * bins + to; b < end; b++) grow(box, s.box, 2 * k * b);
    }

    /**
     * Moves the references whose centroid bin on {@code axis} is below {@code bin} first; returns
     * where the rest start. It bounds each child's centroids as it classifies the references: each
     * is read once, and growing a box twice by the same reference changes nothing.
     */
    private int partition(int from, int to, int axis, int nb, double lo, double scale, int bin, BuildNode left, BuildNode right) {
        double[] lc = left.centroids = new double[2 * k], rc = right.centroids = new double[2 * k];
        clear(lc, 0);
        clear(rc, 0);
        int i = from, j = to - 1;
        while (true) {
            while (i <= j && binOf(centre(i, axis), lo, scale, nb) < bin) growCentroids(lc, i++);
            while (i <= j && binOf(centre(j, axis), lo, scale, nb) >= bin) growCentroids(rc, j--);
            if (i >= j) return i;
            swap(i, j);
        }
    }

    /** Grows a centroid box by reference {@code i}'s (doubled) centroid. */
    private void growCentroids(double[] c, int i) {
        if (k == 3) {   // unrolled: the partition's per-reference work
            float[] r = bounds;
            int o = 6 * i;
            double cx = (double) r[o] + r[o + 3], cy = (double) r[o + 1] + r[o + 4], cz = (double) r[o + 2] + r[o + 5];
            c[0] = Math.min(c[0], cx); c[1] = Math.min(c[1], cy); c[2] = Math.min(c[2], cz);
            c[3] = Math.max(c[3], cx); c[4] = Math.max(c[4], cy); c[5] = Math.max(c[5], cz);
            return;
        }
        for (int a = 0; a < k; a++) {
            double x = centre(i, a);
            c[a] = Math.min(c[a], x);
            c[k + a] = Math.max(c[k + a], x);
        }
    }

    /** Halves the stretch at the median centroid on the widest axis (anywhere if they coincide): the cut that keeps the depth cap. */
    private int median(int from, int to, double[] c) {
        int mid = (from + to) >>> 1, axis = widest(c);
        if (c[k + axis] > c[axis]) select(from, to - 1, mid, axis);
        return mid;
    }

    /** {@return the axis on which the centroid bounds {@code c} spread most (the first of equals)} */
    private int widest(double[] c) {
        int axis = 0;
        for (int a = 1; a < k; a++) if (c[k + a] - c[a] > c[k + axis] - c[axis]) axis = a;
        return axis;
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
            float v = bounds[a + x];
            bounds[a + x] = bounds[b + x];
            bounds[b + x] = v;
        }
    }
}
