package org.kdtree.build;

import org.kdtree.geom.Box;
import org.kdtree.shape.Primitives;
import org.kdtree.tree.KdTreeWriter;

/**
 * The O(N log N) SAH build of Wald and Havran (2006, section 4.3) as primitive-array code: the
 * talk's recConst with the SAH's terminate and findPlane, over events held as a position and an
 * {@code int} code ({@link EventCode}), sorted once at the root and kept sorted through every split
 * ({@link EventSplit}), in scratch memory reused per depth ({@link EventLevels}). No object is
 * made per node or per event.
 *
 * <p>It builds the very tree {@link SahBuilder} builds through {@link KdTreeBuilder}'s recursion
 * with the naive or the sorted search: the same candidates (the clipped bounds),
 * the same costs ({@link SahCost}), the same first minimum ({@link SahSplit}), the same safety
 * nets (depth cap, a split that separates nothing makes a leaf, the {@link ReferenceBudget}), and
 * leaves list their primitives in increasing order, as the recursion's stable partitions do.
 *
 * <p>One engine serves one thread of work: the whole build, or a subtree handed to another
 * thread, which gets an idle engine of the build, with its scratch memory ({@link ForkingEngine}).
 */
final class EventEngine extends ForkingEngine<EventEngine> {
    private final SahBuilder settings;
    private final BuildContext context;
    final Primitives prims;
    final int k;
    final boolean perfectSplits;
    private final int depthCap, forkThreshold;
    final EventLevels levels;
    private final SahCost sah;
    private final SahSplit best = new SahSplit();
    private final EventSplit split;
    private final double leafCostPerPrimitive;
    private int[] leafRefs = new int[16];
    private double[] sortPos = new double[16];
    private int[] sortCode = new int[16];

    EventEngine(SahBuilder settings, BuildContext context) {
        this(settings, context, new java.util.concurrent.ConcurrentLinkedDeque<>());
    }

    private EventEngine(SahBuilder settings, BuildContext context, java.util.Deque<EventEngine> spares) {
        super(spares, context.primitives().dimension());
        this.settings = settings;
        this.context = context;
        this.prims = context.primitives();
        this.k = prims.dimension();
        this.perfectSplits = settings.perfectSplits();
        this.depthCap = context.depthCap();
        this.forkThreshold = context.forkThreshold();
        this.levels = new EventLevels(k);
        this.sah = new SahCost(settings.costModel(), settings.emptyWeight(), k);
        this.split = new EventSplit(this);
        this.leafCostPerPrimitive = settings.costModel().ki();
    }

    /** Whether the engine can build over {@code context} (at most 2^30 primitives). */
    static boolean applies(BuildContext context) {
        return context.primitives().size() < EventCode.MAX_PRIMITIVES;
    }

    /** Builds the whole tree into {@code out}. */
    void build(Box rootVoxel, KdTreeWriter out) {
        reserve(out, prims.size());
        EventRoot.write(this, rootVoxel);
        levels.budget(0)[0] = ReferenceBudget.root(settings.referenceBudget(), prims.size());
        recConst(0, 0, out);
    }

    /**
     * Builds the subtree of a node handed over at depth {@code d} (by the binned engine, below its
     * exact threshold): voxel at {@code voxel[voxelAt ..]}, references {@code refs[refsAt ..]} with
     * clipped bounds at slots {@code boundsAt ..}; the same subtree the recursion would build.
     */
    void buildSubtree(int d, double[] voxel, int voxelAt, int[] refs, int refsAt, double[] bounds, int boundsAt, int n,
                      long budget, KdTreeWriter out) {
        levels.rebase(d);
        EventRoot.write(this, d, voxel, voxelAt, refs, refsAt, bounds, boundsAt, n, false);
        levels.budget(d)[0] = budget;
        recConst(d, 0, out);
    }

    /** Sort scratch for at least {@code n} positions (and as many codes, {@link #sortCodes}). */
    double[] sortPositions(int n) {
        if (sortPos.length < n) {
            sortPos = new double[EventLevels.grown(sortPos.length, n)];
            sortCode = new int[sortPos.length];
        }
        return sortPos;
    }

    int[] sortCodes() { return sortCode; }

    @Override EventEngine newSpare(java.util.Deque<EventEngine> spares) {
        return new EventEngine(settings, context, spares);
    }

    @Override int copyRightChild(int d, EventEngine other) {
        levels.copyChild(d, 1, other.levels);
        return levels.meta(d)[levels.metaAt(1)];
    }

    /** recConst for child c of level d (the root is child 0 of level 0). */
    @Override void recConst(int d, int c, KdTreeWriter out) {
        int n = levels.meta(d)[levels.metaAt(c)];
        if (n == 0 || d >= depthCap || !findPlane(d, c, n)) {
            leaf(d, c, n, out);
            return;
        }
        int axis = best.axis();
        double xi = best.position();
        int done = split.split(d, c, n, axis, xi, best.planarLeft());
        if (done != SplitOutcome.SPLIT) {
            if (done == SplitOutcome.OVER_BUDGET) out.budgetLeaf();
            leaf(d, c, n, out);
            return;
        }
        int interior = out.interior(axis, xi);
        int[] below = levels.meta(d + 1);
        if (below[levels.metaAt(1)] >= forkThreshold && below[levels.metaAt(0)] > 0) {
            forkRight(d + 1, interior, out);
            return;
        }
        recConst(d + 1, 0, out);
        out.setRightChild(interior);
        recConst(d + 1, 1, out);
    }

    /**
     * The SAH's terminate and findPlane in one search: sweeps every axis, keeps the first plane
     * of least cost in {@link #best}, and answers whether it beats a leaf ({@code |T| Ki}).
     */
    private boolean findPlane(int d, int c, int n) {
        sah.set(levels.voxel(d), 2 * k * c);
        if (!(sah.halfArea() > 0)) return false;
        best.reset();
        double[] pos = levels.positions(d);
        int[] code = levels.codes(d), meta = levels.meta(d);
        int at = levels.metaAt(c);
        for (int axis = 0; axis < k; axis++)
            sweep(axis, n, pos, code, meta[at + 1 + 2 * axis], meta[at + 2 + 2 * axis]);
        return best.found() && best.cost() < n * leafCostPerPrimitive;
    }

    /**
     * One axis: events grouped by position; at each position the plane is offered with
     * |T_L| (references starting before it or lying in planes before it), |T_P| (lying in it)
     * and |T_R| (ending after it), as {@link SortedPlaneSearch#sweep} counts them.
     */
    private void sweep(int axis, int n, double[] pos, int[] code, int from, int to) {
        int nl = 0, nr = n, i = from;
        while (i < to) {
            double x = pos[i];
            int group = 0, planar = 0, start = 0;
            for (; i < to && pos[i] == x; i++) {
                if (x == 0) x = Math.min(x, pos[i]);   // -0.0 if the group has one, as the other searches pick
                int kind = EventCode.kind(code[i]);    // END 0, PLANAR 1, START 2: counted without branches
                group++;
                planar += kind & 1;
                start += kind >>> 1;
            }
            nr -= group - start;
            best.offer(sah, axis, x, nl, planar, nr);
            nl += start + planar;
        }
    }

    /** Writes child c of level d as a leaf: its primitives (one start or planar event each on axis 0), in increasing order. */
    private void leaf(int d, int c, int n, KdTreeWriter out) {
        if (leafRefs.length < n) leafRefs = new int[EventLevels.grown(leafRefs.length, n)];
        int[] code = levels.codes(d), meta = levels.meta(d);
        int at = levels.metaAt(c), m = 0;
        for (int e = meta[at + 1], to = meta[at + 2]; e < to; e++)
            if (EventCode.kind(code[e]) != EventCode.END) leafRefs[m++] = EventCode.primitive(code[e]);
        java.util.Arrays.sort(leafRefs, 0, m);
        out.leaf(leafRefs, 0, m);
    }
}
