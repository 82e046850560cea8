package org.kdtree.build;

import org.kdtree.limits.Limits;
import org.kdtree.geom.Box;
import org.kdtree.geom.SplitPlane;
import org.kdtree.tree.CostModel;
import org.kdtree.tree.KdTreeWriter;

/**
 * Chooses planes by the surface area heuristic (talk, section 3.3): among the candidate
 * planes at the clipped bounds of every primitive on every axis, the one of least cost
 * {@code C_V(p)} (see {@link SahCost}); terminates automatically when no plane is cheaper than
 * a leaf ({@code min C_V(p) >= |T| Ki}), and at the depth cap.
 *
 * <p>Defaults: Kt = 15, Ki = 20, empty-voxel weight lambda = 0.8, depth cap
 * {@code 8 + 1.3 log2 N}, perfect splits on, plane search {@link Algorithm#EVENT}.
 */
public class SahBuilder extends KdTreeBuilder {
    /**
     * How the best plane of a node is found. Every exact algorithm builds the same tree. Each
     * carries its own strategy: the plane search the recursion runs per node, and, for EVENT and
     * BINNED, the primitive-array engine that builds the very tree of that recursion.
     */
    public enum Algorithm {
        /** Count each candidate by scanning all primitives: O(N^2). */
        NAIVE {
            @Override PlaneSearch search(SahBuilder sah) { return NAIVE_SEARCH; }
        },
        /** Sort each node's events, then sweep: O(N log^2 N). */
        SORTED {
            @Override PlaneSearch search(SahBuilder sah) { return SORTED_SEARCH; }
        },
        /**
         * Sort the events once at the root, keep them sorted through every split: O(N log N), in
         * the primitive-array {@link EventEngine}. A subclass of this builder (which may override
         * terminate or findPlane) gets the recursion with the sorted search: the same tree.
         */
        EVENT {
            @Override PlaneSearch search(SahBuilder sah) { return SORTED_SEARCH; }

            @Override boolean hasEngine() { return true; }

            @Override void runEngine(SahBuilder sah, BuildContext context, Box rootVoxel, KdTreeWriter out) {
                new EventEngine(sah, context).build(rootVoxel, out);
            }
        },
        /**
         * Not exact: only the boundaries of {@link #bins()} equal bins per axis are candidates,
         * counted from histograms; nodes smaller than {@link #exactBelow()} get the exact sweep.
         * No sorting, at some cost in tree quality; the primitive-array {@link BinnedEngine}.
         */
        BINNED {
            @Override PlaneSearch search(SahBuilder sah) { return new BinnedPlaneSearch(sah.bins(), sah.exactBelow()); }

            @Override boolean hasEngine() { return true; }

            @Override void runEngine(SahBuilder sah, BuildContext context, Box rootVoxel, KdTreeWriter out) {
                new BinnedEngine(sah, context).build(rootVoxel, out);
            }

            @Override public boolean exact() { return false; }
        };

        /** The plane search the recursion runs at each node, under {@code sah}'s settings. */
        abstract PlaneSearch search(SahBuilder sah);

        /** Whether a primitive-array engine builds the whole tree (else the recursion does). */
        boolean hasEngine() { return false; }

        /** Builds the whole tree with the engine; only when {@link #hasEngine()}. */
        void runEngine(SahBuilder sah, BuildContext context, Box rootVoxel, KdTreeWriter out) {
            throw new IllegalStateException(this + " has no engine");
        }

        /** {@return whether this algorithm finds the plane of least cost} (NAIVE, SORTED and EVENT do). */
        public boolean exact() { return true; }
    }

    private static final PlaneSearch NAIVE_SEARCH = new NaivePlaneSearch(), SORTED_SEARCH = new SortedPlaneSearch();

    /** The default number of bins per axis of {@link Algorithm#BINNED}. */
    public static final int DEFAULT_BINS = 32;

    /** The default node size below which {@link Algorithm#BINNED} searches exactly. */
    public static final int DEFAULT_EXACT_BELOW = 64;

    private double emptyWeight = 0.8;
    private Algorithm algorithm = Algorithm.EVENT;
    private int bins = DEFAULT_BINS;
    private int exactBelow = DEFAULT_EXACT_BELOW;

    @Override public String name() { return "sah"; }

    @Override protected boolean terminate(BuildContext context, BuildNode node) {
        if (node.size() == 0 || node.depth() >= context.depthCap()) return true;
        SahCost sah = new SahCost(costModel(), emptyWeight, node.voxel());
        if (!(sah.halfArea() > 0)) return true;
        SahSplit best = new SahSplit();
        algorithm.search(this).search(node, sah, best);
        if (!best.found() || best.cost() >= sah.leafCost(node.size())) return true;
        node.choose(best.plane());
        return false;
    }

    /**
     * The event and binned algorithms run in engines of their own ({@link EventEngine},
     * {@link BinnedEngine}), which build the tree the recursion would; a subclass (which may
     * override terminate or findPlane) always gets the recursion.
     */
    @Override protected void construct(BuildContext context, Box rootVoxel, KdTreeWriter out) {
        if (getClass() == SahBuilder.class && algorithm.hasEngine() && EventEngine.applies(context))
            algorithm.runEngine(this, context, rootVoxel, out);
        else super.construct(context, rootVoxel, out);
    }

    @Override protected SplitPlane findPlane(BuildContext context, BuildNode node) {
        if (node.chosen() == null && terminate(context, node))
            throw new IllegalStateException("findPlane called on a node the SAH would make a leaf");
        return node.chosen();
    }

    /** {@return lambda, the weight of a plane that leaves one child empty} (default 0.8; 1 disables the bonus). */
    public double emptyWeight() { return emptyWeight; }

    /**
     * Sets lambda ({@link Limits#LAMBDA}: 0.01 .. 1).
     *
     * @param lambda the weight
     * @return this builder
     */
    public SahBuilder emptyWeight(double lambda) {
        this.emptyWeight = Limits.LAMBDA.check("emptyWeight (lambda)", lambda);
        return this;
    }

    /** {@return the plane-search algorithm} (default EVENT). */
    public Algorithm algorithm() { return algorithm; }

    /**
     * Chooses the plane-search algorithm (the tree is the same; the build time is not).
     *
     * @param a the algorithm
     * @return this builder
     */
    public SahBuilder algorithm(Algorithm a) {
        this.algorithm = java.util.Objects.requireNonNull(a);
        return this;
    }

    /** {@return B, the number of bins per axis of {@link Algorithm#BINNED}} (default 32). */
    public int bins() { return bins; }

    /**
     * Sets B (2 .. 1,000,000) for {@link Algorithm#BINNED}; ignored by the exact algorithms.
     *
     * @param b the number of bins
     * @return this builder
     */
    public SahBuilder bins(int b) {
        this.bins = Limits.BINS.check("bins", b);
        return this;
    }

    /**
     * {@return the node size below which {@link Algorithm#BINNED} uses the exact sweep} (default 64; 0 = bins everywhere).
     */
    public int exactBelow() { return exactBelow; }

    /**
     * Sets the node size below which {@link Algorithm#BINNED} uses the exact sweep (>= 0).
     *
     * @param n the node size
     * @return this builder
     */
    public SahBuilder exactBelow(int n) {
        this.exactBelow = Limits.EXACT_BELOW.check("exactBelow", n);
        return this;
    }

    /**
     * Sets Kt and Ki together.
     *
     * @param kt Kt, the cost of traversing a node
     * @param ki Ki, the cost of intersecting a primitive
     * @return this builder
     */
    public SahBuilder costs(double kt, double ki) {
        costModel(new CostModel(kt, ki));
        return this;
    }

    @Override public SahBuilder costModel(CostModel model) { super.costModel(model); return this; }

    @Override public SahBuilder maxDepth(int depth) { super.maxDepth(depth); return this; }

    @Override public SahBuilder depthFactor(double c) { super.depthFactor(c); return this; }

    @Override public SahBuilder referenceBudget(int perPrimitive) { super.referenceBudget(perPrimitive); return this; }

    /**
     * Applies a named preset ({@link Quality}): the event algorithm under that preset's depth cap.
     *
     * @param q the preset
     * @return this builder
     */
    public SahBuilder quality(Quality q) { return q.applyTo(this); }

    @Override public SahBuilder perfectSplits(boolean on) { super.perfectSplits(on); return this; }

    @Override public SahBuilder threads(int n) { super.threads(n); return this; }

    @Override public String describeSettings() {
        return "lambda=" + emptyWeight + " algorithm=" + algorithm.name().toLowerCase()
                + (!algorithm.exact() ? " bins=" + bins + " exactBelow=" + exactBelow : "") + " " + super.describeSettings();
    }
}
