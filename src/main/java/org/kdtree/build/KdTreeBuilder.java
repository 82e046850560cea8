package org.kdtree.build;

import java.util.Deque;
import java.util.concurrent.ConcurrentLinkedDeque;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.ForkJoinTask;
import org.kdtree.limits.Limits;
import org.kdtree.geom.Box;
import org.kdtree.geom.SplitPlane;
import org.kdtree.shape.InvalidGeometryException;
import org.kdtree.shape.Primitives;
import org.kdtree.tree.CostModel;
import org.kdtree.tree.KdTree;
import org.kdtree.tree.KdTreeWriter;

/**
 * The talk's Algorithm 1, written once, for every builder:
 * <pre>
 * recConst(T, V):
 *   if terminate(T, V): return Leaf(T)
 *   p = findPlane(T, V)
 *   (V_L, V_R) = cut V with p
 *   T_L = { t in T | t overlaps V_L },  T_R = { t in T | t overlaps V_R }
 *   return Node(p, recConst(T_L, V_L), recConst(T_R, V_R))
 * </pre>
 * Subclasses decide {@link #terminate} and {@link #findPlane}, and nothing else: the cut, the
 * partition and the recursion are the library's, run over one node store of flat arrays
 * reused through the build ({@link NodeStore}; a {@link BuildNode} is a view of one of its
 * nodes). The SAH's fast searches are answers to those two questions like any other
 * (docs/algorithms.md maps the talk's pseudo-code to this code line by line).
 *
 * <p>Safety nets stand around the subclass's decisions, so that no input can make a build run
 * away: the recursion never goes deeper than {@link #maxDepth()} (default
 * {@code 8 + 1.3 log2 N}); a split that sends every primitive to both children (it separates
 * nothing, as with thousands of coincident triangles) makes a leaf instead; and so does a split
 * whose children would exceed the node's share of the {@link #referenceBudget()}. What the
 * subclass throws or answers wrong is reported as its fault ({@link BuilderFault}).
 *
 * <p>A builder is configured before use and may be reused; {@link #build} is safe to call
 * from several threads only if the subclass keeps no per-build state in fields.
 */
public abstract class KdTreeBuilder {
    /** Depth beyond which no setting can go: 2^64 voxels would not fit in any memory ({@link Limits#MAX_DEPTH}). */
    public static final int DEPTH_LIMIT = (int) Limits.MAX_DEPTH.max();

    /** c in the automatic depth cap {@code 8 + c log2 N} (pbrt's and Wald and Havran's 1.3). */
    public static final double DEFAULT_DEPTH_FACTOR = 1.3;

    // Each setting starts from its row of the one table, Setting.
    private int maxDepth = Setting.MAX_DEPTH.defaultValue();
    private double depthFactor = DEFAULT_DEPTH_FACTOR;
    private int referenceBudget = Setting.REFERENCE_BUDGET.defaultValue();
    private CostModel costModel = new CostModel(Setting.KT.defaultValue(), Setting.KI.defaultValue());
    private boolean perfectSplits = Setting.PERFECT_SPLITS.defaultValue();
    private int threads = Setting.THREADS.defaultValue();

    /**
     * Builds the tree of {@code primitives}, starting from their bounding box (constKdTree).
     *
     * @throws java.util.concurrent.CancellationException if the calling thread is interrupted
     *         during the build (the build stops at its next node)
     * @throws BuilderFault if this builder's terminate or findPlane throws or returns a plane
     *         the recursion cannot use
     * @param primitives the scene's primitives
     * @return the tree
     */
    public final KdTree build(Primitives primitives) {
        return build(primitives, BuildWatch.unwatched());
    }

    /** {@link #build(Primitives)} under {@code watch}: a supervisor's view of the build, and its way to stop it. */
    final KdTree build(Primitives primitives, BuildWatch watch) {
        Box rootVoxel = rootVoxel(primitives);
        int n = primitives.size();
        Build build = new Build(primitives, depthCap(n), threads == 1 ? Integer.MAX_VALUE : forkThreshold(n, threads), watch,
                new ConcurrentLinkedDeque<>());
        KdTreeWriter out = new KdTreeWriter(primitives.dimension());
        reserve(out, n);
        watch.threads(threads);
        if (threads == 1) {
            recConstRoot(build, rootVoxel, out);
        } else {
            ForkJoinPool pool = new ForkJoinPool(threads);
            try {
                pool.invoke(ForkJoinTask.adapt(() -> recConstRoot(build, rootVoxel, out)));
            } catch (RuntimeException | Error e) {
                watch.cancel(null); // the subtrees still under way on other threads stop at their next node
                throw e;
            } finally {
                pool.shutdown();
            }
        }
        return out.finish(rootVoxel, costModel, name());
    }

    /** The root: every primitive with its own bounds, in the scene's box, with the whole reference budget. */
    private void recConstRoot(Build build, Box rootVoxel, KdTreeWriter out) {
        NodeStore store = new NodeStore(build.primitives);
        store.writeRoot(rootVoxel, ReferenceBudget.root(referenceBudget, build.primitives.size()));
        recConst(build, store, 0, 0, out);
    }

    /**
     * recConst for child c of level d of {@code store} (the root is child 0 of level 0): the one
     * place where Algorithm 1 is written. The node's children go to level d + 1.
     */
    private void recConst(Build build, NodeStore store, int d, int c, KdTreeWriter out) {
        BuildNode node = store.view.point(d, c);
        build.watch.node(++store.nodes);
        if (d >= build.depthCap || BuilderCalls.terminate(this, build, build.watch, node)) {
            store.leaf(d, c, out);
            return;
        }
        SplitPlane p = BuilderCalls.findPlane(this, build, build.watch, node);
        int outcome = store.split(d, c, p.axis(), p.position(), p.planarLeft(), perfectSplits);
        if (outcome != SplitOutcome.SPLIT) {
            if (outcome == SplitOutcome.OVER_BUDGET) out.budgetLeaf();
            store.leaf(d, c, out);
            return;
        }
        int interior = out.interior(p.axis(), p.position());
        if (build.forkThreshold != Integer.MAX_VALUE && store.size(d + 1, 1) >= build.forkThreshold && store.size(d + 1, 0) > 0) {
            forkRight(build, store, d + 1, interior, out);
            return;
        }
        recConst(build, store, d + 1, 0, out);
        out.setRightChild(interior);
        recConst(build, store, d + 1, 1, out);
    }

    /**
     * Both children of level d, the right one built by another thread: copied into an idle
     * store of the build (with its writer, reused from fork to fork), built there while this
     * thread builds the left one, then spliced in after it. The same recursion, so the same tree,
     * in the same depth-first order.
     */
    private void forkRight(Build build, NodeStore store, int d, int interior, KdTreeWriter out) {
        Spare spare = build.spares.poll();
        if (spare == null) spare = new Spare(new NodeStore(build.primitives), new KdTreeWriter(store.k));
        Spare other = spare;
        int n = store.copyChild(d, 1, other.store);
        ForkJoinTask<?> right = ForkJoinTask.adapt(() -> {
            other.out.clear();
            reserve(other.out, n);
            recConst(build, other.store, d, 1, other.out);
        }).fork();
        recConst(build, store, d, 0, out);
        right.join();
        out.setRightChild(interior);
        out.append(other.out);
        build.spares.push(other);
    }

    /** An idle store and writer for a subtree handed to another thread. */
    private record Spare(NodeStore store, KdTreeWriter out) {
    }

    /**
     * Sizes {@code out} up front for the tree of {@code primitives} primitives, where the
     * builder can tell (the SAH can), rather than growing it by doubling.
     */
    void reserve(KdTreeWriter out, int primitives) {
    }

    /**
     * The smallest right child handed to another thread: small enough that every thread finds
     * work (about 32 tasks per thread), big enough that a task is worth its copy into the
     * parent's output (at least 2,048 primitives).
     */
    private static int forkThreshold(int n, int threads) {
        return Math.max(2048, n / (32 * threads));
    }

    /** {@return the name under which this builder is reported, e.g. "sah"} */
    public abstract String name();

    /**
     * terminate(T, V): should this node become a leaf?
     *
     * @param context the build in progress
     * @param node the node T, V
     * @return true to make the node a leaf
     */
    protected abstract boolean terminate(BuildContext context, BuildNode node);

    /**
     * findPlane(T, V): the split plane for a node that does not terminate.
     *
     * @param context the build in progress
     * @param node the node T, V
     * @return the plane to split it with
     */
    protected abstract SplitPlane findPlane(BuildContext context, BuildNode node);

    private static Box rootVoxel(Primitives primitives) {
        int k = primitives.dimension();
        Box all = new Box(k), b = new Box(k);
        for (int i = 0; i < primitives.size(); i++) {
            primitives.bounds(i, b);
            if (!b.isFinite() || b.isEmpty())
                throw new InvalidGeometryException(primitives.describe(i) + " has non-finite or empty bounds " + b);
            all.grow(b);
        }
        if (all.isEmpty()) for (int a = 0; a < k; a++) all.setMin(a, 0).setMax(a, 0);
        return all;
    }

    /**
     * The default depth cap, {@code round(8 + 1.3 log2 N)}, as pbrt and Wald and Havran use.
     *
     * @param n N, the number of primitives
     * @return the cap
     */
    public static int defaultMaxDepth(int n) {
        return automaticDepthCap(n, DEFAULT_DEPTH_FACTOR);
    }

    private static int automaticDepthCap(int n, double factor) {
        double log2 = n <= 1 ? 0 : Math.log(n) / Math.log(2);
        return (int) Math.min(DEPTH_LIMIT, Math.round(8 + factor * log2));
    }

    /**
     * The depth cap a build over {@code n} primitives uses: Kmaxdepth if set, else {@code round(8 + c log2 N)}.
     *
     * @param n N, the number of primitives
     * @return the cap
     */
    public final int depthCap(int n) {
        return maxDepth >= 0 ? maxDepth : automaticDepthCap(n, depthFactor);
    }

    // ---- settings ----

    /** {@return Kmaxdepth, or -1 for the default {@code 8 + 1.3 log2 N}} */
    public int maxDepth() { return maxDepth; }

    /**
     * Sets Kmaxdepth (0 .. 64), or -1 for the default {@code 8 + 1.3 log2 N}.
     *
     * @param depth Kmaxdepth, or -1
     * @return this builder
     */
    public KdTreeBuilder maxDepth(int depth) {
        this.maxDepth = Limits.MAX_DEPTH.check("maxDepth", depth);
        return this;
    }

    /** {@return c in the automatic depth cap {@code 8 + c log2 N}} (default 1.3), used when Kmaxdepth is not set. */
    public double depthFactor() { return depthFactor; }

    /**
     * Sets c (0 .. 4) in the automatic depth cap {@code 8 + c log2 N}: a lower cap builds a
     * smaller tree faster at some cost in quality (the SAH's quality presets set it).
     * @param c the factor
     * @return this builder
     */
    public KdTreeBuilder depthFactor(double c) {
        this.depthFactor = Limits.DEPTH_FACTOR.check("depthFactor", c);
        return this;
    }

    /**
     * {@return B, the references per input primitive the tree may hold at the most} ({@link ReferenceBudget}; default: {@link Setting#REFERENCE_BUDGET}).
     */
    public int referenceBudget() { return referenceBudget; }

    /**
     * Sets B (1 .. 65,536): the tree holds at most B references per input primitive; where the
     * geometry would need more, nodes become leaves early and the tree says how many
     * ({@link KdTree#budgetLeaves()}).
     * @param perPrimitive B
     * @return this builder
     */
    public KdTreeBuilder referenceBudget(int perPrimitive) {
        this.referenceBudget = Limits.REFERENCE_BUDGET.check("referenceBudget", perPrimitive);
        return this;
    }

    /** {@return Kt and Ki}: the SAH uses them to choose planes; every tree reports its expected cost with them. */
    public CostModel costModel() { return costModel; }

    /**
     * Sets Kt and Ki (default: {@link Setting#KT} and {@link Setting#KI}, Wald and Havran's {@link CostModel#WALD_HAVRAN}).
     *
     * @param model Kt and Ki
     * @return this builder
     */
    public KdTreeBuilder costModel(CostModel model) {
        Limits.KT.check("Kt", model.kt());
        Limits.KI.check("Ki", model.ki());
        this.costModel = model;
        return this;
    }

    /** {@return whether straddling primitives are clipped to each child voxel} (default: {@link Setting#PERFECT_SPLITS}). */
    public boolean perfectSplits() { return perfectSplits; }

    /**
     * Turns perfect splits on (exact clipping, the default) or off (bounding boxes only).
     *
     * @param on true for perfect splits
     * @return this builder
     */
    public KdTreeBuilder perfectSplits(boolean on) {
        this.perfectSplits = on;
        return this;
    }

    /** {@return the number of threads a build uses} (default: {@link Setting#THREADS}). */
    public int threads() { return threads; }

    /**
     * Sets the number of threads (1 .. 256). With more than one, independent subtrees are built
     * in parallel (fork/join); the tree is the same as with one thread.
     * @param n the number of threads
     * @return this builder
     */
    public KdTreeBuilder threads(int n) {
        this.threads = Limits.THREADS.check("threads", n);
        return this;
    }

    /** {@return a one-line summary of the settings}, e.g. for the command line. */
    public String describeSettings() {
        return "maxDepth=" + (maxDepth >= 0 ? String.valueOf(maxDepth)
                : depthFactor == DEFAULT_DEPTH_FACTOR ? "auto" : "auto(8+" + depthFactor + " log2 N)") + " Kt=" + costModel.kt() + " Ki=" + costModel.ki()
                + " perfectSplits=" + perfectSplits + (threads > 1 ? " threads=" + threads : "")
                + (referenceBudget != Setting.REFERENCE_BUDGET.defaultValue() ? " referenceBudget=" + referenceBudget : "");
    }

    /** The per-build context that {@link BuildContext} exposes to subclasses. */
    private record Build(Primitives primitives, int depthCap, int forkThreshold, BuildWatch watch, Deque<Spare> spares)
            implements BuildContext {
    }
}
