package org.kdtree.bvh;

import java.util.List;
import org.kdtree.accel.CostModel;
import org.kdtree.accel.Setting;
import org.kdtree.accel.Settings;
import org.kdtree.accel.SharedSettings;
import org.kdtree.accel.StructureBuilder;
import org.kdtree.limits.Limits;
import org.kdtree.shape.Primitives;

/**
 * Builds a {@link Bvh}, a binary tree whose nodes bound groups of whole primitives, top-down by
 * the binned SAH over primitive bounds with the kd-trees' cost model (Kt, Ki), so that both
 * structures are judged by one model; a node of at most {@link #leafSize()} primitives becomes a
 * leaf when splitting costs more. Rays trace it collapsed to {@link #width()} children per node (docs/bvh.md).
 *
 * <p>Its settings are one {@link Settings} value over its rows: the shared ones ({@link SharedSettings})
 * and its own width. A builder is not thread safe; a build may be.
 */
public final class BvhBuilder implements StructureBuilder {
    /** The name the command line, the workbench and the study know it by. */
    public static final String NAME = "bvh";
    /** The depth no node goes beyond (and the automatic cap): the stack of every traversal is sized by it. */
    public static final int DEPTH_LIMIT = (int) Limits.MAX_DEPTH.max();

    /** Children per node of the wide layout, the one rays traverse. */
    public static final Setting<Integer> WIDTH = Setting.whole("--bvh-width", Limits.BVH_WIDTH, 4,
            "children per node of the collapsed layout that rays traverse (the binary tree is built first)");

    private static final List<Setting<?>> ROWS = List.of(SharedSettings.KT, SharedSettings.KI, SharedSettings.MAX_DEPTH,
            SharedSettings.THREADS, SharedSettings.BINS, SharedSettings.LEAF_SIZE, WIDTH);

    private Settings settings = Settings.DEFAULTS;

    /** {@return "bvh"} */
    @Override public String name() { return NAME; }

    /** {@return Kt, Ki, Kmaxdepth, threads, bins, leaf size and width} */
    @Override public List<Setting<?>> settingRows() { return ROWS; }

    @Override public Settings settings() { return settings; }

    @Override public BvhBuilder configure(Settings settings) {
        this.settings = StructureBuilder.checkTakes(this, settings);
        return this;
    }

    /**
     * Builds the hierarchy of {@code primitives} (those whose bounds are empty are left out: no ray can hit them).
     *
     * @param primitives the scene's primitives
     * @return the hierarchy, in its binary and wide layouts
     * @throws java.util.concurrent.CancellationException if the calling thread is interrupted
     */
    @Override public Bvh build(Primitives primitives) {
        return BinnedBuild.build(primitives, this);
    }

    private <T> BvhBuilder with(Setting<T> row, T value) {
        return configure(settings.with(row, value));
    }

    /** {@return Kt and Ki, for the SAH and the expected cost} */
    public CostModel costModel() { return SharedSettings.costModel(settings); }

    /**
     * Sets Kt and Ki.
     * @param model the cost model
     * @return this builder
     */
    public BvhBuilder costModel(CostModel model) { return configure(SharedSettings.withCostModel(settings, model)); }

    /** {@return threads building the hierarchy (the same hierarchy at any count)} */
    public int threads() { return settings.get(SharedSettings.THREADS); }

    /**
     * Sets the threads building.
     * @param n threads ({@link Limits#THREADS})
     * @return this builder
     */
    public BvhBuilder threads(int n) { return with(SharedSettings.THREADS, n); }

    /** {@return Kmaxdepth, or -1 for the automatic cap ({@link #DEPTH_LIMIT})} */
    public int maxDepth() { return settings.get(SharedSettings.MAX_DEPTH); }

    /**
     * Sets the depth cap: no node deeper is split, whatever its size.
     * @param depth the cap, or -1 ({@link Limits#MAX_DEPTH})
     * @return this builder
     */
    public BvhBuilder maxDepth(int depth) { return with(SharedSettings.MAX_DEPTH, depth); }

    /** {@return the depth cap this builder uses, whatever the number of primitives: Kmaxdepth if given, else {@link #DEPTH_LIMIT}} */
    @Override public int depthCap(int primitives) { return maxDepth() >= 0 ? maxDepth() : DEPTH_LIMIT; }

    /** {@return bins per axis of the binned SAH (a node of fewer primitives uses one bin each)} */
    public int bins() { return settings.get(SharedSettings.BINS); }

    /**
     * Sets the bins per axis.
     * @param n bins ({@link Limits#BINS})
     * @return this builder
     */
    public BvhBuilder bins(int n) { return with(SharedSettings.BINS, n); }

    /** {@return the largest leaf: a node of more primitives is always split (unless at the depth cap)} */
    public int leafSize() { return settings.get(SharedSettings.LEAF_SIZE); }

    /**
     * Sets the largest leaf.
     * @param n primitives ({@link Limits#LEAF_SIZE})
     * @return this builder
     */
    public BvhBuilder leafSize(int n) { return with(SharedSettings.LEAF_SIZE, n); }

    /** {@return children per node of the wide layout that rays traverse} */
    public int width() { return settings.get(WIDTH); }

    /**
     * Sets the children per node of the wide layout.
     * @param n 2 to 8 ({@link Limits#BVH_WIDTH})
     * @return this builder
     */
    public BvhBuilder width(int n) { return with(WIDTH, n); }

    /** {@return a one-line summary of the settings}, e.g. for the command line */
    @Override public String describeSettings() {
        CostModel cost = costModel();
        return "width=" + width() + " bins=" + bins() + " leafSize=" + leafSize() + " maxDepth=" + (maxDepth() >= 0 ? maxDepth() : "auto")
                + " Kt=" + cost.kt() + " Ki=" + cost.ki() + (threads() > 1 ? " threads=" + threads() : "");
    }
}
