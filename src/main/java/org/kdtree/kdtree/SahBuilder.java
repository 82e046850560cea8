package org.kdtree.kdtree;

import java.util.List;
import java.util.Locale;
import org.kdtree.accel.CostModel;
import org.kdtree.accel.Setting;
import org.kdtree.accel.Settings;
import org.kdtree.accel.SharedSettings;
import org.kdtree.geom.SplitPlane;
import org.kdtree.limits.Limits;

/**
 * Chooses planes by the surface area heuristic (talk, section 3.3): among the candidate
 * planes at the clipped bounds of every primitive on every axis, the one of least cost
 * {@code C_V(p)} ({@link SahCost}); a leaf when no plane is cheaper than a leaf
 * ({@code min C_V(p) >= |T| Ki}, section 3.3.3), unless the path may still try a few more
 * ({@link #lookahead()}, the talk's "a few more iterations").
 *
 * <p>Deciding terminate needs the best plane, so {@link #terminate} searches for it (by the
 * {@link Algorithm} set) and keeps it on the node ({@link BuildNode#keepPlane}, as a student's
 * builder does), and {@link #findPlane} returns what was kept. Its settings and presets are
 * {@link SahSettings}; a subclass runs the same searches over the same node store.
 */
public class SahBuilder extends KdTreeBuilder {
    private static final PlaneSearch NAIVE_SEARCH = new NaivePlaneSearch();

    /** The plane search of the settings it was made for (made again when they change). */
    private PlaneSearch search;
    private Settings searchFor;

    @Override public String name() { return "sah"; }

    /**
     * A leaf if the node is empty or smaller than {@link #leafBelow()}, at the depth cap, or flat (no ray meets it with positive
     * probability), or if no plane is cheaper than the leaf and the path has made its {@link #lookahead()} of trial splits;
     * else keeps the best plane found (on trial if it is not cheaper than the leaf).
     */
    @Override protected boolean terminate(BuildContext context, BuildNode node) {
        if (node.size() < leafBelow() || node.depth() >= context.depthCap()) return true;
        Search s = node.state(Search.class);
        if (s == null) node.keepState(s = new Search(new SahCost(costModel(), lambda(), node.dimension())));
        SahCost sah = s.cost.set(node.store().voxel(node.level()), 2 * node.dimension() * node.child());
        if (!(sah.halfArea() > 0)) return true;
        SahSplit best = s.best;
        best.reset();
        search().search(node, sah, best);
        if (!best.found()) return true;
        if (best.cost() >= sah.leafCost(node.size())) {
            if (node.trialSplits() >= lookahead()) return true;
            node.keepTrialPlane(best.plane()); // past a local minimum, perhaps: tried, kept only if it pays
            return false;
        }
        node.keepPlane(best.plane());
        return false;
    }

    /** The plane {@link #terminate} found and kept (searching now if this node's terminate did not). */
    @Override protected SplitPlane findPlane(BuildContext context, BuildNode node) {
        if (node.keptPlane() == null && terminate(context, node))
            throw new IllegalStateException("findPlane called on a node the SAH would make a leaf");
        return node.keptPlane();
    }

    /** What the SAH keeps from node to node on one thread ({@link BuildNode#state}): its cost function and its best plane. */
    private record Search(SahCost cost, SahSplit best) {
        Search(SahCost cost) { this(cost, new SahSplit()); }
    }

    /** {@return the plane search these settings name} */
    private PlaneSearch search() {
        Settings now = settings();
        if (now != searchFor) {
            search = searchOf(algorithm());
            searchFor = now;
        }
        return search;
    }

    private PlaneSearch searchOf(Algorithm a) {
        return switch (a) {
            case NAIVE -> NAIVE_SEARCH;
            case SORTED -> SortedPlaneSearch.INSTANCE;
            case EVENT -> EventSweep.INSTANCE;
            case BINNED -> new BinnedPlaneSearch(bins(), exactBelow());
        };
    }

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

    /** {@return the preset given, or null} */
    public Quality quality() { return settings().given(SahSettings.QUALITY); }

    /**
     * Gives the preset {@code q}: its plane search and leaf size, with the automatic depth cap
     * (a plane search, bins, exact threshold, leaf size or Kmaxdepth given before is dropped; give
     * one after the preset to override it); Kt, Ki, lambda, perfect splits and threads are left alone.
     *
     * @param q the preset
     * @return this builder
     */
    public SahBuilder quality(Quality q) {
        configure(SahSettings.withQuality(settings(), q));
        depthFactor(KdTreeBuilder.DEFAULT_DEPTH_FACTOR);
        return this;
    }

    /** {@return the splits still made along a path where no plane beats the leaf, each on trial} (default 0) */
    public int lookahead() { return settings().get(SahSettings.LOOKAHEAD); }

    /**
     * Sets the lookahead: along a path, up to {@code n} splits whose cost does not beat the leaf
     * are still made, and each subtree is kept only where it ends cheaper than the leaf it replaced.
     *
     * @param n splits ({@link Limits#LOOKAHEAD})
     * @return this builder
     */
    public SahBuilder lookahead(int n) { with(SahSettings.LOOKAHEAD, n); return this; }

    /** {@return lambda, the weight of a plane that leaves one child empty} */
    public double lambda() { return settings().get(SahSettings.LAMBDA); }

    /**
     * Sets lambda.
     *
     * @param lambda the weight ({@link Limits#LAMBDA})
     * @return this builder
     */
    public SahBuilder lambda(double lambda) { with(SahSettings.LAMBDA, lambda); return this; }

    /** {@return the plane search: as given, else the preset's, else EVENT} */
    public Algorithm algorithm() { return SahSettings.algorithm(settings()); }

    /**
     * Sets the plane search.
     *
     * @param a the algorithm
     * @return this builder
     */
    public SahBuilder algorithm(Algorithm a) { with(SahSettings.ALGORITHM, a); return this; }

    /** {@return bins per axis of the binned search} */
    public int bins() { return settings().get(SharedSettings.BINS); }

    /**
     * Sets the bins per axis of the binned search.
     *
     * @param b bins ({@link Limits#BINS})
     * @return this builder
     */
    public SahBuilder bins(int b) { with(SharedSettings.BINS, b); return this; }

    /** {@return the node size below which the binned search sweeps exactly: as given, else the preset's, else 64} */
    public int exactBelow() { return SahSettings.exactBelow(settings()); }

    /**
     * Sets the exact threshold of the binned search.
     *
     * @param n references ({@link Limits#EXACT_BELOW})
     * @return this builder
     */
    public SahBuilder exactBelow(int n) { with(SahSettings.EXACT_BELOW, n); return this; }

    /** {@return the smallest node searched for a plane: as given, else the preset's, else 1} */
    public int leafBelow() { return SahSettings.leafBelow(settings()); }

    /**
     * Sets the smallest node searched for a plane.
     *
     * @param n references ({@link Limits#LEAF_BELOW})
     * @return this builder
     */
    public SahBuilder leafBelow(int n) { with(SahSettings.LEAF_BELOW, n); return this; }

    /**
     * Sets Kt and Ki.
     *
     * @param kt the cost of a traversal step
     * @param ki the cost of a primitive test
     * @return this builder
     */
    public SahBuilder costs(double kt, double ki) {
        costModel(new CostModel(kt, ki));
        return this;
    }

    /** {@return the preset, the kd-tree builders' rows, then lambda, plane search, bins, exact threshold, leaf size and lookahead} ({@link SahSettings}) */
    @Override public List<Setting<?>> settingRows() { return SahSettings.ROWS; }

    @Override public String describeSettings() {
        Algorithm algorithm = algorithm();
        return "lambda=" + lambda() + " algorithm=" + algorithm.name().toLowerCase(Locale.ROOT)
                + (!algorithm.exact() ? " bins=" + bins() + " exactBelow=" + exactBelow() : "")
                + (leafBelow() > 1 ? " leafBelow=" + leafBelow() : "")
                + (lookahead() > 0 ? " lookahead=" + lookahead() : "") + " " + super.describeSettings();
    }
}
