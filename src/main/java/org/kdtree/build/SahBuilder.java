package org.kdtree.build;

import org.kdtree.limits.Limits;
import org.kdtree.geom.SplitPlane;
import org.kdtree.tree.CostModel;
import org.kdtree.tree.KdTreeWriter;

/**
 * Chooses planes by the surface area heuristic (talk, section 3.3): among the candidate
 * planes at the clipped bounds of every primitive on every axis, the one of least cost
 * {@code C_V(p)} (see {@link SahCost}); terminates automatically when no plane is cheaper than
 * a leaf ({@code min C_V(p) >= |T| Ki}, section 3.3.3), and at the depth cap.
 *
 * <p>Deciding terminate needs the best plane, so {@link #terminate} searches for it and keeps it,
 * and {@link #findPlane} returns what was kept: one search per node, by whichever
 * {@link Algorithm} is set. (A student's builder keeps its plane with {@link BuildNode#keepPlane};
 * this one keeps it in its search state, one per thread of the build, so that no plane object is
 * made per node.) A subclass gets the same searches over the same node store as this class:
 * there is no other path.
 *
 * <p>Its settings and their defaults are rows of {@link Setting} (docs/limits.md lists them):
 * those of every builder, and {@link Setting#LAMBDA}, {@link Setting#ALGORITHM},
 * {@link Setting#BINS}, {@link Setting#EXACT_BELOW} and the preset {@link Setting#QUALITY}.
 */
public class SahBuilder extends KdTreeBuilder {
    /** How the best plane of a node is found. Every exact algorithm builds the same tree. */
    public enum Algorithm {
        /** Count each candidate by scanning all primitives: O(N^2) per node. */
        NAIVE,
        /** Sort each node's events, then sweep: O(N log^2 N) for the build. */
        SORTED,
        /**
         * Sort the events once at the root, keep them sorted through every split, sweep them at
         * each node: O(N log N) for the build ({@link EventSweep}, {@link EventSplit}).
         */
        EVENT,
        /**
         * Not exact: only the boundaries of {@link #bins()} equal bins per axis are candidates,
         * counted from histograms; nodes smaller than {@link #exactBelow()} get the exact event
         * sweep. No sorting above that size, at some cost in tree quality.
         */
        BINNED {
            @Override public boolean exact() { return false; }
        };

        /** {@return whether this algorithm finds the plane of least cost} (NAIVE, SORTED and EVENT do). */
        public boolean exact() { return true; }
    }

    private static final PlaneSearch NAIVE_SEARCH = new NaivePlaneSearch(), SORTED_SEARCH = new SortedPlaneSearch();

    /**
     * Nodes and leaf references an SAH tree has per primitive, a little above what the meshes
     * measured gave (bunny 8.9 and 5.3, its 4 x 4 grid 9.5 and 5.6).
     */
    private static final int NODES_PER_PRIMITIVE = 10, REFS_PER_PRIMITIVE = 6;

    private double lambda = Setting.LAMBDA.defaultValue();
    private Algorithm algorithm = Setting.ALGORITHM.defaultValue();
    private int bins = Setting.BINS.defaultValue();
    private int exactBelow = Setting.EXACT_BELOW.defaultValue();
    private int leafBelow = Setting.LEAF_BELOW.defaultValue();
    private PlaneSearch search = searchOf(algorithm);

    @Override public String name() { return "sah"; }

    /**
     * A leaf if the node is empty or smaller than {@link #leafBelow()}, at the depth cap, or flat (no ray meets it with positive
     * probability), or if no plane is cheaper than the leaf; else keeps the best plane found.
     */
    @Override protected boolean terminate(BuildContext context, BuildNode node) {
        if (node.size() < leafBelow || node.depth() >= context.depthCap()) return true;
        NodeStore store = node.store();
        if (store.sahCost == null) store.sahCost = new SahCost(costModel(), lambda, node.dimension());
        SahCost sah = store.sahCost.set(store.voxel(node.level()), 2 * node.dimension() * node.child());
        if (!(sah.halfArea() > 0)) return true;
        SahSplit best = store.best;
        best.reset();
        search.search(node, sah, best);
        if (!best.found() || best.cost() >= sah.leafCost(node.size())) return true;
        node.searched = true;
        return false;
    }

    /** The plane {@link #terminate} found and kept (searching now if this node's terminate did not). */
    @Override protected SplitPlane findPlane(BuildContext context, BuildNode node) {
        if (!node.searched && terminate(context, node))
            throw new IllegalStateException("findPlane called on a node the SAH would make a leaf");
        return node.store().best.plane();
    }

    @Override void reserve(KdTreeWriter out, int primitives) {
        out.reserve((int) Math.min(1 << 26, (long) NODES_PER_PRIMITIVE * primitives),
                (int) Math.min(1 << 28, (long) REFS_PER_PRIMITIVE * primitives));
    }

    /** The plane search of {@code a} under this builder's bins and exact threshold. */
    private PlaneSearch searchOf(Algorithm a) {
        return switch (a) {
            case NAIVE -> NAIVE_SEARCH;
            case SORTED -> SORTED_SEARCH;
            case EVENT -> EventSweep.INSTANCE;
            case BINNED -> new BinnedPlaneSearch(bins, exactBelow);
        };
    }

    /** {@return lambda, the weight of a plane that leaves one child empty} (1 disables the bonus; default: {@link Setting#LAMBDA}). */
    public double lambda() { return lambda; }

    /**
     * Sets lambda ({@link Limits#LAMBDA}: 0.01 .. 1).
     *
     * @param lambda the weight
     * @return this builder
     */
    public SahBuilder lambda(double lambda) {
        this.lambda = Limits.LAMBDA.check("lambda", lambda);
        return this;
    }

    /** {@return the plane-search algorithm} (default: {@link Setting#ALGORITHM}). */
    public Algorithm algorithm() { return algorithm; }

    /**
     * Chooses the plane-search algorithm (the tree is the same; the build time is not).
     *
     * @param a the algorithm
     * @return this builder
     */
    public SahBuilder algorithm(Algorithm a) {
        this.algorithm = java.util.Objects.requireNonNull(a);
        this.search = searchOf(a);
        return this;
    }

    /** {@return B, the number of bins per axis of {@link Algorithm#BINNED}} (default: {@link Setting#BINS}). */
    public int bins() { return bins; }

    /**
     * Sets B (2 .. 1,000,000) for {@link Algorithm#BINNED}; ignored by the exact algorithms.
     *
     * @param b the number of bins
     * @return this builder
     */
    public SahBuilder bins(int b) {
        this.bins = Limits.BINS.check("bins", b);
        this.search = searchOf(algorithm);
        return this;
    }

    /**
     * {@return the node size below which {@link Algorithm#BINNED} uses the exact sweep} (0 = bins everywhere; default: {@link Setting#EXACT_BELOW}).
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
        this.search = searchOf(algorithm);
        return this;
    }

    /**
     * {@return the node size below which a node becomes a leaf without a plane search} (default 1:
     * only empty nodes; the SAH alone decides the others).
     */
    public int leafBelow() { return leafBelow; }

    /**
     * Makes every node of fewer than {@code n} primitives a leaf ({@link Limits#LEAF_BELOW}: 1 ..
     * 65,536). Near the leaves the greedy SAH goes on cutting a few triangles apart for small local
     * savings that do not add up (docs/performance.md, "Quality presets"): stopping at a few
     * primitives builds far fewer nodes for about the same expected cost.
     *
     * @param n the smallest node searched
     * @return this builder
     */
    public SahBuilder leafBelow(int n) {
        this.leafBelow = Limits.LEAF_BELOW.check("leafBelow", n);
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
     * Applies a named preset ({@link Quality}): its plane search and leaf size.
     *
     * @param q the preset
     * @return this builder
     */
    public SahBuilder quality(Quality q) { return q.applyTo(this); }

    @Override public SahBuilder perfectSplits(boolean on) { super.perfectSplits(on); return this; }

    @Override public SahBuilder threads(int n) { super.threads(n); return this; }

    @Override public String describeSettings() {
        return "lambda=" + lambda + " algorithm=" + algorithm.name().toLowerCase()
                + (!algorithm.exact() ? " bins=" + bins + " exactBelow=" + exactBelow : "")
                + (leafBelow > 1 ? " leafBelow=" + leafBelow : "") + " " + super.describeSettings();
    }
}
