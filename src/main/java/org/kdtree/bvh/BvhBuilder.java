package org.kdtree.bvh;

import org.kdtree.limits.Limits;
import org.kdtree.shape.Primitives;
import org.kdtree.tree.CostModel;

/**
 * Builds a {@link Bvh}, a bounding volume hierarchy: a binary tree whose nodes bound groups of
 * whole primitives, found top-down by the binned SAH over primitive bounds with the same cost
 * model (Kt, Ki) as the kd-tree builders, so that the two structures are judged by one model.
 * A node becomes a leaf when splitting it costs more than testing its primitives and it holds
 * at most {@link #leafSize()}; the binary tree is then collapsed into a wide layout of
 * {@link #width()} children per node for tracing (docs/bvh.md).
 *
 * <p>Its settings are rows of the one builder specification ({@code build.Setting}): Kt, Ki,
 * threads, Kmaxdepth, bins, leaf size and width. A builder is not thread safe; a build may be.
 */
public final class BvhBuilder {
    /** The name the command line, the workbench and the study know it by. */
    public static final String NAME = "bvh";
    /** The depth no node goes beyond (and the automatic cap): the stack of every traversal is sized by it. */
    public static final int DEPTH_LIMIT = (int) Limits.MAX_DEPTH.max();

    private CostModel costModel = CostModel.WALD_HAVRAN;
    private int threads = 1;
    private int maxDepth = -1;
    private int bins = 32;
    private int leafSize = 16;
    private int width = 4;

    /** {@return "bvh"} */
    public String name() { return NAME; }

    /**
     * Builds the hierarchy of {@code primitives} (those whose bounds are empty are left out: no ray can hit them).
     *
     * @param primitives the scene's primitives
     * @return the hierarchy, in its binary and wide layouts
     * @throws java.util.concurrent.CancellationException if the calling thread is interrupted
     */
    public Bvh build(Primitives primitives) {
        return BinnedBuild.build(primitives, this);
    }

    /** {@return Kt and Ki, for the SAH and the expected cost} */
    public CostModel costModel() { return costModel; }

    /**
     * Sets Kt and Ki.
     *
     * @param model the cost model
     * @return this builder
     */
    public BvhBuilder costModel(CostModel model) {
        this.costModel = java.util.Objects.requireNonNull(model, "costModel");
        return this;
    }

    /** {@return threads building the hierarchy (the same hierarchy at any count)} */
    public int threads() { return threads; }

    /**
     * Sets the threads building.
     *
     * @param n threads ({@link Limits#THREADS})
     * @return this builder
     */
    public BvhBuilder threads(int n) {
        this.threads = Limits.THREADS.check("threads", n);
        return this;
    }

    /** {@return Kmaxdepth, or -1 for the automatic cap ({@link #DEPTH_LIMIT})} */
    public int maxDepth() { return maxDepth; }

    /**
     * Sets the depth cap: no node deeper is split, whatever its size.
     *
     * @param depth the cap, or -1 ({@link Limits#MAX_DEPTH})
     * @return this builder
     */
    public BvhBuilder maxDepth(int depth) {
        this.maxDepth = Limits.MAX_DEPTH.check("Kmaxdepth", depth);
        return this;
    }

    /** {@return the depth cap this builder uses} */
    int depthCap() { return maxDepth >= 0 ? maxDepth : DEPTH_LIMIT; }

    /** {@return bins per axis of the binned SAH (a node of fewer primitives uses one bin each)} */
    public int bins() { return bins; }

    /**
     * Sets the bins per axis.
     *
     * @param n bins ({@link Limits#BINS})
     * @return this builder
     */
    public BvhBuilder bins(int n) {
        this.bins = Limits.BINS.check("bins", n);
        return this;
    }

    /** {@return the largest leaf: a node of more primitives is always split (unless at the depth cap)} */
    public int leafSize() { return leafSize; }

    /**
     * Sets the largest leaf.
     *
     * @param n primitives ({@link Limits#LEAF_SIZE})
     * @return this builder
     */
    public BvhBuilder leafSize(int n) {
        this.leafSize = Limits.LEAF_SIZE.check("leaf size", n);
        return this;
    }

    /** {@return children per node of the wide layout that rays traverse} */
    public int width() { return width; }

    /**
     * Sets the children per node of the wide layout.
     *
     * @param n 2 to 8 ({@link Limits#BVH_WIDTH})
     * @return this builder
     */
    public BvhBuilder width(int n) {
        this.width = Limits.BVH_WIDTH.check("BVH width", n);
        return this;
    }

    /** {@return a one-line summary of the settings}, e.g. for the command line */
    public String describeSettings() {
        return "width=" + width + " bins=" + bins + " leafSize=" + leafSize + " maxDepth=" + (maxDepth >= 0 ? maxDepth : "auto")
                + " Kt=" + costModel.kt() + " Ki=" + costModel.ki() + (threads > 1 ? " threads=" + threads : "");
    }
}
