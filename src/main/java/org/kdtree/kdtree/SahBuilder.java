package org.kdtree.kdtree;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.stream.Collectors;
import org.kdtree.accel.CostModel;
import org.kdtree.accel.Setting;
import org.kdtree.accel.Settings;
import org.kdtree.accel.SharedSettings;
import org.kdtree.geom.SplitPlane;
import org.kdtree.limits.Limits;

/**
 * Chooses planes by the surface area heuristic (talk, section 3.3): among the candidate
 * planes at the clipped bounds of every primitive on every axis, the one of least cost
 * {@code C_V(p)} (see {@link SahCost}); terminates automatically when no plane is cheaper than
 * a leaf ({@code min C_V(p) >= |T| Ki}, section 3.3.3), and at the depth cap.
 *
 * <p>Deciding terminate needs the best plane, so {@link #terminate} searches for it and keeps it,
 * and {@link #findPlane} returns what was kept: one search per node, by whichever
 * {@link Algorithm} is set. It keeps that plane with {@link BuildNode#keepPlane}, as a student's
 * builder does, and its search state (cost function, best plane) in {@link BuildNode#keepState}, the
 * door any builder has; the exact search sweeps the node's sorted events, which a
 * student's builder reads through {@link BuildNode#eventCount} and its neighbours. A subclass gets the same
 * searches over the same node store as this class: there is no other path.
 *
 * <p>Its settings and their defaults are rows of {@link Setting} (docs/limits.md lists them):
 * those of every builder, and {@link SahBuilder#LAMBDA}, {@link SahBuilder#ALGORITHM},
 * {@link SharedSettings#BINS}, {@link SahBuilder#EXACT_BELOW} and the preset {@link SahBuilder#QUALITY}.
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

    /** A named preset (plane search and leaf size); first of the rows, so that the others, if given, override it. */
    public static final Setting<Quality> QUALITY = Setting.choice("quality", "--quality", Quality.class, null,
            "a named SAH preset, " + Arrays.stream(Quality.values())
                    .map(q -> q.name().toLowerCase(Locale.ROOT) + " (" + q.describe() + ")")
                    .collect(Collectors.joining(", ")) + "; the other settings, if given, override it");
    /** lambda, the weight of a plane that leaves one child empty. */
    public static final Setting<Double> LAMBDA = Setting.real("--lambda", Limits.LAMBDA, 0.8,
            "the SAH's weight of a plane that cuts off empty space (1 = no bonus)");
    /** The plane search. */
    public static final Setting<Algorithm> ALGORITHM = Setting.choice("plane search", "--algorithm", Algorithm.class, Algorithm.EVENT,
            "how the SAH searches for its planes (NAIVE, SORTED and EVENT build the same tree in different times; "
                    + "BINNED builds another, with planes at bin boundaries only)");
    /** The node size below which the binned search sweeps exactly. */
    public static final Setting<Integer> EXACT_BELOW = Setting.whole("--exact-below", Limits.EXACT_BELOW, 64,
            "the BINNED plane search sweeps nodes of fewer references exactly");
    /** The smallest node searched for a plane. */
    public static final Setting<Integer> LEAF_BELOW = Setting.whole("--leaf-below", Limits.LEAF_BELOW, 1,
            "nodes of fewer references become leaves without a plane search (1 = only empty ones)");

    /** Splits still made along a path past the leaf criterion, on trial. */
    public static final Setting<Integer> LOOKAHEAD = Setting.whole("--lookahead", Limits.LOOKAHEAD, 0,
            "splits still made along a path where no plane beats the leaf (the talk's \"a few more iterations\"); "
                    + "each subtree is kept only where it ends cheaper than the leaf");

    /** The preset first, then every kd-tree builder's rows, then the SAH's own. */
    private static final List<Setting<?>> ROWS = rows();

    private static List<Setting<?>> rows() {
        List<Setting<?>> rows = new ArrayList<>();
        rows.add(QUALITY);
        rows.addAll(KdTreeBuilder.ROWS);
        rows.addAll(List.of(LAMBDA, ALGORITHM, SharedSettings.BINS, EXACT_BELOW, LEAF_BELOW, LOOKAHEAD));
        return List.copyOf(rows);
    }

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

    /** The plane search of {@code a} under this builder's bins and exact threshold. */
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
            case SORTED -> SORTED_SEARCH;
            case EVENT -> EventSweep.INSTANCE;
            case BINNED -> new BinnedPlaneSearch(bins(), exactBelow());
        };
    }

    /** {@return lambda, the weight of a plane that leaves one child empty} (1 disables the bonus; default: {@link SahBuilder#LAMBDA}). */
    /** {@return the preset given, or null} */
    public Quality quality() { return settings().given(QUALITY); }

    /**
     * Gives the preset {@code q}: its plane search and leaf size, with the automatic depth cap
     * (a plane search, bins, exact threshold, leaf size or Kmaxdepth given before is dropped; give
     * one after the preset to override it); Kt, Ki, lambda, perfect splits and threads are left alone.
     *
     * @param q the preset
     * @return this builder
     */
    public SahBuilder quality(Quality q) {
        Settings s = settings();
        for (Setting<?> row : List.of(ALGORITHM, SharedSettings.BINS, EXACT_BELOW, LEAF_BELOW, SharedSettings.MAX_DEPTH))
            s = s.with(row, null);
        configure(s.with(QUALITY, q));
        depthFactor(KdTreeBuilder.DEFAULT_DEPTH_FACTOR);
        return this;
    }

    /** {@return the splits still made along a path where no plane beats the leaf, each on trial} (default 0) */
    public int lookahead() { return settings().get(LOOKAHEAD); }

    /**
     * Sets the lookahead: along a path, up to {@code n} splits whose cost does not beat the leaf
     * are still made, and each subtree is kept only where it ends cheaper than the leaf it replaced.
     *
     * @param n splits ({@link Limits#LOOKAHEAD})
     * @return this builder
     */
    public SahBuilder lookahead(int n) { with(LOOKAHEAD, n); return this; }

    /** {@return lambda, the weight of a plane that leaves one child empty} */
    public double lambda() { return settings().get(LAMBDA); }

    /**
     * Sets lambda.
     *
     * @param lambda the weight ({@link Limits#LAMBDA})
     * @return this builder
     */
    public SahBuilder lambda(double lambda) { with(LAMBDA, lambda); return this; }

    /** {@return the plane search: as given, else the preset's, else EVENT} */
    public Algorithm algorithm() { return givenOrPreset(ALGORITHM, Quality::algorithm); }

    /** A row's value as given, else the preset's (where it sets one), else the row's default. */
    private <T> T givenOrPreset(Setting<T> row, java.util.function.Function<Quality, T> ofPreset) {
        T given = settings().given(row);
        if (given != null) return given;
        T preset = quality() != null ? ofPreset.apply(quality()) : null;
        return preset != null ? preset : row.defaultValue();
    }

    /**
     * Sets the plane search.
     *
     * @param a the algorithm
     * @return this builder
     */
    public SahBuilder algorithm(Algorithm a) { with(ALGORITHM, a); return this; }

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
    public int exactBelow() { return givenOrPreset(EXACT_BELOW, q -> q.exactBelow() >= 0 ? q.exactBelow() : null); }

    /**
     * Sets the exact threshold of the binned search.
     *
     * @param n references ({@link Limits#EXACT_BELOW})
     * @return this builder
     */
    public SahBuilder exactBelow(int n) { with(EXACT_BELOW, n); return this; }

    /** {@return the smallest node searched for a plane: as given, else the preset's, else 1} */
    public int leafBelow() { return givenOrPreset(LEAF_BELOW, Quality::leafBelow); }

    /**
     * Sets the smallest node searched for a plane.
     *
     * @param n references ({@link Limits#LEAF_BELOW})
     * @return this builder
     */
    public SahBuilder leafBelow(int n) { with(LEAF_BELOW, n); return this; }

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

    /** {@return the preset, the kd-tree builders' rows, then lambda, plane search, bins, exact threshold and leaf size} */
    @Override public List<Setting<?>> settingRows() { return ROWS; }

    @Override public String describeSettings() {
        Algorithm algorithm = algorithm();
        return "lambda=" + lambda() + " algorithm=" + algorithm.name().toLowerCase(Locale.ROOT)
                + (!algorithm.exact() ? " bins=" + bins() + " exactBelow=" + exactBelow() : "")
                + (leafBelow() > 1 ? " leafBelow=" + leafBelow() : "")
                + (lookahead() > 0 ? " lookahead=" + lookahead() : "") + " " + super.describeSettings();
    }
}
