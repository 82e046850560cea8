package org.kdtree.build;

import java.util.Deque;
import java.util.concurrent.ConcurrentLinkedDeque;
import org.kdtree.geom.Box;
import org.kdtree.shape.Primitives;
import org.kdtree.tree.KdTreeWriter;

/**
 * Binned SAH (Wald 2007; Popov et al. 2006) as primitive-array code: the talk's recConst over
 * flat arrays of references and their clipped bounds, O(k (|T| + B)) per node with no sorting
 * ({@link BinnedPlaneSearch#searchAxis}), in scratch memory reused per depth
 * ({@link BinnedLevels}). A node below {@link SahBuilder#exactBelow()} references is handed with
 * its whole subtree to the {@link EventEngine}, which searches exactly from there on.
 *
 * <p>It builds the very tree the recursion builds with {@link SahBuilder.Algorithm#BINNED}: the
 * same histograms and candidates, the same costs and first minimum, the same partition
 * ({@link Partition#classify}, {@link Partition#straddlerBounds}) in the same order, the same
 * safety nets (depth cap, separates nothing, {@link ReferenceBudget}).
 */
final class BinnedEngine extends ForkingEngine<BinnedEngine> {
    private final Primitives prims;
    private final int k, bins, exactBelow, depthCap, forkThreshold;
    private final boolean perfectSplits;
    private final double leafCostPerPrimitive;
    private final SahBuilder settings;
    private final BuildContext context;
    private final BinnedLevels levels;
    private final SahCost sah;
    private final SahSplit best = new SahSplit();
    private final int[] minBin, maxBin;
    private final Box voxel, clipLeft, clipRight;
    private EventEngine exact;

    BinnedEngine(SahBuilder settings, BuildContext context) {
        this(settings, context, new ConcurrentLinkedDeque<>());
    }

    private BinnedEngine(SahBuilder settings, BuildContext context, Deque<BinnedEngine> spares) {
        super(spares, context.primitives().dimension());
        this.settings = settings;
        this.context = context;
        this.prims = context.primitives();
        this.k = prims.dimension();
        this.bins = settings.bins();
        this.exactBelow = settings.exactBelow();
        this.depthCap = context.depthCap();
        this.forkThreshold = context.forkThreshold();
        this.perfectSplits = settings.perfectSplits();
        this.leafCostPerPrimitive = settings.costModel().ki();
        this.levels = new BinnedLevels(k);
        this.sah = new SahCost(settings.costModel(), settings.emptyWeight(), k);
        this.minBin = new int[bins];
        this.maxBin = new int[bins];
        this.voxel = new Box(k);
        this.clipLeft = new Box(k);
        this.clipRight = new Box(k);
    }

    @Override BinnedEngine newSpare(Deque<BinnedEngine> spares) {
        return new BinnedEngine(settings, context, spares);
    }

    @Override int copyRightChild(int d, BinnedEngine other) {
        levels.copyChild(d, 1, other.levels);
        return levels.meta(d)[3];
    }

    /** Builds the whole tree into {@code out}. */
    void build(Box rootVoxel, KdTreeWriter out) {
        int n = prims.size();
        reserve(out, n);
        levels.reserve(0, n);
        int[] refs = levels.refs(0);
        for (int i = 0; i < n; i++) refs[i] = i;
        Partition.writeAllBounds(prims, levels.bounds(0));
        int[] meta = levels.meta(0);
        meta[0] = 0;
        meta[1] = n;
        double[] v = levels.voxel(0);
        for (int a = 0; a < k; a++) {
            v[a] = rootVoxel.min(a);
            v[k + a] = rootVoxel.max(a);
        }
        levels.budget(0)[0] = ReferenceBudget.root(settings.referenceBudget(), n);
        recConst(0, 0, out);
    }

    /** recConst for child c of level d (the root is child 0 of level 0). */
    @Override void recConst(int d, int c, KdTreeWriter out) {
        int[] meta = levels.meta(d);
        int from = meta[2 * c], n = meta[2 * c + 1];
        if (n == 0 || d >= depthCap) {
            out.leaf(levels.refs(d), from, n);
            return;
        }
        if (n < exactBelow) {
            exactEngine().buildSubtree(d, levels.voxel(d), 2 * k * c, levels.refs(d), from, levels.bounds(d), from, n,
                    levels.budget(d)[c], out);
            return;
        }
        if (!findPlane(d, c, from, n)) {
            out.leaf(levels.refs(d), from, n);
            return;
        }
        int axis = best.axis();
        double xi = best.position();
        int done = split(d, c, from, n, axis, xi, best.planarLeft());
        if (done != SplitOutcome.SPLIT) {
            if (done == SplitOutcome.OVER_BUDGET) out.budgetLeaf();
            out.leaf(levels.refs(d), from, n);
            return;
        }
        int interior = out.interior(axis, xi);
        int[] below = levels.meta(d + 1);
        if (below[3] >= forkThreshold && below[1] > 0) {
            forkRight(d + 1, interior, out);
            return;
        }
        recConst(d + 1, 0, out);
        out.setRightChild(interior);
        recConst(d + 1, 1, out);
    }

    private EventEngine exactEngine() {
        if (exact == null) exact = new EventEngine(settings, context);
        return exact;
    }

    /** terminate and findPlane: the binned search of every axis; whether its plane beats a leaf. */
    private boolean findPlane(int d, int c, int from, int n) {
        double[] v = levels.voxel(d);
        sah.set(v, 2 * k * c);
        if (!(sah.halfArea() > 0)) return false;
        best.reset();
        double[] bounds = levels.bounds(d);
        for (int axis = 0; axis < k; axis++)
            BinnedPlaneSearch.searchAxis(sah, best, axis, v[2 * k * c + axis], v[2 * k * c + k + axis], bins, minBin, maxBin,
                    bounds, from, n, k);
        return best.found() && best.cost() < n * leafCostPerPrimitive;
    }

    /**
     * The recursion's partition ({@link Partition#split}) into level d + 1: references in node
     * order, the left child's from 0, the right's after room for all left candidates; a straddler
     * gets its clipped bounds in each child it reaches, and the children their shares of the node's
     * reference budget. Like {@link EventSplit#split}, returns the {@link SplitOutcome}.
     */
    private int split(int d, int c, int from, int n, int axis, double xi, boolean planarLeft) {
        int[] refs = levels.refs(d);
        double[] bounds = levels.bounds(d);
        int nl = 0, nr = 0;
        for (int j = from; j < from + n; j++) {
            double lo = bounds[2 * k * j + axis], hi = bounds[2 * k * j + k + axis];
            Partition.Side s = Partition.classify(lo, hi, xi, planarLeft);
            if (s != Partition.Side.RIGHT) nl++;
            if (s != Partition.Side.LEFT) nr++;
        }
        levels.reserve(d + 1, nl + nr);
        int[] outRefs = levels.refs(d + 1);
        double[] outBounds = levels.bounds(d + 1);
        double[] v = levels.voxel(d);
        for (int a = 0; a < k; a++) voxel.setMin(a, v[2 * k * c + a]).setMax(a, v[2 * k * c + k + a]);
        int il = 0, ir = nl;
        for (int j = from; j < from + n; j++) {
            int prim = refs[j];
            switch (Partition.classify(bounds[2 * k * j + axis], bounds[2 * k * j + k + axis], xi, planarLeft)) {
                case LEFT -> { outRefs[il] = prim; System.arraycopy(bounds, 2 * k * j, outBounds, 2 * k * il++, 2 * k); }
                case RIGHT -> { outRefs[ir] = prim; System.arraycopy(bounds, 2 * k * j, outBounds, 2 * k * ir++, 2 * k); }
                case BOTH -> {
                    int to = Partition.straddlerBounds(prims, prim, bounds, j, voxel, axis, xi, perfectSplits, clipLeft, clipRight,
                            outBounds, il, outBounds, ir);
                    if ((to & 1) != 0) outRefs[il++] = prim;
                    if ((to & 2) != 0) outRefs[ir++] = prim;
                }
            }
        }
        int sizeL = il, sizeR = ir - nl;
        long budget = levels.budget(d)[c];
        int outcome = SplitOutcome.of(n, sizeL, sizeR, budget);
        if (outcome != SplitOutcome.SPLIT) return outcome;
        long[] shares = levels.budget(d + 1);
        shares[0] = ReferenceBudget.share(budget, sizeL, sizeL, sizeR);
        shares[1] = ReferenceBudget.share(budget, sizeR, sizeL, sizeR);
        int[] below = levels.meta(d + 1);
        below[0] = 0;
        below[1] = sizeL;
        below[2] = nl;
        below[3] = sizeR;
        double[] vb = levels.voxel(d + 1);
        System.arraycopy(v, 2 * k * c, vb, 0, 2 * k);
        System.arraycopy(v, 2 * k * c, vb, 2 * k, 2 * k);
        vb[k + axis] = xi;
        vb[2 * k + axis] = xi;
        return SplitOutcome.SPLIT;
    }
}
