package org.kdtree.kdtree;

import java.util.Deque;
import java.util.List;
import java.util.concurrent.ConcurrentLinkedDeque;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.ForkJoinTask;
import org.kdtree.accel.CostModel;
import org.kdtree.accel.Setting;
import org.kdtree.accel.Settings;
import org.kdtree.accel.SharedSettings;
import org.kdtree.accel.StructureBuilder;
import org.kdtree.geom.Box;
import org.kdtree.geom.SplitPlane;
import org.kdtree.limits.Limits;
import org.kdtree.shape.InvalidGeometryException;
import org.kdtree.shape.Primitives;

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
 * <p>Its settings are one immutable {@link Settings} value ({@link #configure}, or a setter, which
 * gives one row); it reads them from there. A subclass that takes rows of its own lists them in
 * {@link #settingRows()}, and the command line and the workbench show them.
 *
 * <p>A builder is configured before use and may be reused; {@link #build} is safe to call
 * from several threads only if the subclass keeps no per-build state in fields.
 */
public abstract class KdTreeBuilder implements StructureBuilder {
    /** Depth beyond which no setting can go: 2^64 voxels would not fit in any memory ({@link Limits#MAX_DEPTH}). */
    public static final int DEPTH_LIMIT = (int) Limits.MAX_DEPTH.max();

    /** c in the automatic depth cap {@code 8 + c log2 N} (pbrt's and Wald and Havran's 1.3). */
    public static final double DEFAULT_DEPTH_FACTOR = 1.3;

    /** B, the references per input primitive the tree may hold. */
    public static final Setting<Integer> REFERENCE_BUDGET = Setting.whole("--reference-budget", Limits.REFERENCE_BUDGET, 256,
            "references per primitive the tree may hold: where overlapping geometry would need more, "
                    + "nodes become leaves early and the statistics say so");
    /** Whether straddling primitives are clipped exactly to each child (the option turns it off). */
    public static final Setting<Boolean> PERFECT_SPLITS = Setting.onOff("perfect splits", "--no-perfect-splits", true,
            "a primitive that straddles a split plane is clipped to each child exactly, not kept whole by its bounding box");

    /** The rows every kd-tree builder takes. */
    static final List<Setting<?>> ROWS = List.of(SharedSettings.KT, SharedSettings.KI, SharedSettings.MAX_DEPTH,
            REFERENCE_BUDGET, PERFECT_SPLITS, SharedSettings.THREADS);

    private Settings settings = Settings.DEFAULTS;
    /** Kt and Ki as the settings give them, kept whole for the plane searches, which read them at every node. */
    private CostModel costModel = SharedSettings.costModel(settings);
    private double depthFactor = DEFAULT_DEPTH_FACTOR;

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
        int threads = threads();
        Build build = new Build(primitives, depthCap(n), threads == 1 ? Integer.MAX_VALUE : forkThreshold(n, threads), watch,
                new ConcurrentLinkedDeque<>(), perfectSplits());
        KdTreeWriter out = new KdTreeWriter(primitives.dimension());
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
        return out.finish(primitives, rootVoxel, costModel, name());
    }

    /** The root: every primitive with its own bounds, in the scene's box, with the whole reference budget. */
    private void recConstRoot(Build build, Box rootVoxel, KdTreeWriter out) {
        NodeStore store = new NodeStore(build.primitives);
        store.writeRoot(rootVoxel, ReferenceBudget.root(referenceBudget(), build.primitives.size()));
        recConst(build, store, 0, 0, 0, out);
    }

    /**
     * recConst for child c of level d of {@code store} (the root is child 0 of level 0), below
     * {@code trials} splits made on trial: the one place where Algorithm 1 is written. The node's
     * children go to level d + 1.
     *
     * <p>A split made on trial ({@link BuildNode#keepTrialPlane}) is kept only if its subtree's
     * expected cost ends below its leaf's; else the subtree is written over by that leaf (the node
     * is still in level d: its children lived below it). So under a trial every node returns its
     * subtree's cost, weighted by area as the tree's statistics weigh it (Kt SA(V) for an interior
     * node, Ki |T| SA(V) for a leaf); elsewhere it returns 0, and costs nothing.
     */
    private double recConst(Build build, NodeStore store, int d, int c, int trials, KdTreeWriter out) {
        BuildNode node = store.view.point(d, c, trials);
        build.watch.node(++store.nodes);
        if (d >= build.depthCap || BuilderCalls.terminate(this, build, build.watch, node))
            return leaf(store, d, c, trials > 0 ? node.voxel().surfaceArea() : 0, out);
        SplitPlane p = BuilderCalls.findPlane(this, build, build.watch, node);
        boolean trial = node.onTrial();
        double area = trials > 0 || trial ? node.voxel().surfaceArea() : 0;
        int outcome = store.split(d, c, p.axis(), p.position(), p.planarLeft(), build.perfectSplits);
        if (outcome != SplitOutcome.SPLIT) {
            if (outcome == SplitOutcome.OVER_BUDGET) out.budgetLeaf();
            return leaf(store, d, c, area, out);
        }
        KdTreeWriter.Mark before = trial ? out.mark() : null;
        int interior = out.interior(p.axis(), p.position()), below = trial ? trials + 1 : trials;
        double cost = costModel.kt() * area;
        if (build.forkThreshold != Integer.MAX_VALUE && store.size(d + 1, 1) >= build.forkThreshold && store.size(d + 1, 0) > 0) {
            cost += forkRight(build, store, d + 1, below, interior, out);
        } else {
            cost += recConst(build, store, d + 1, 0, below, out);
            out.setRightChild(interior);
            cost += recConst(build, store, d + 1, 1, below, out);
        }
        if (!trial || cost < leafCost(store, d, c, area)) return cost;
        out.rewind(before);
        return leaf(store, d, c, area, out);
    }

    /** Writes child c of level d as a leaf; returns its cost weighted by {@code area} (0 if not measured). */
    private double leaf(NodeStore store, int d, int c, double area, KdTreeWriter out) {
        store.leaf(d, c, out);
        return leafCost(store, d, c, area);
    }

    private double leafCost(NodeStore store, int d, int c, double area) {
        return costModel.ki() * store.size(d, c) * area;
    }

    /**
     * Both children of level d, the right one built by another thread: copied into an idle
     * store of the build (with its writer, reused from fork to fork), built there while this
     * thread builds the left one, then spliced in after it. The same recursion, so the same tree,
     * in the same depth-first order; returns the two subtrees' cost as recConst does.
     */
    private double forkRight(Build build, NodeStore store, int d, int trials, int interior, KdTreeWriter out) {
        Spare spare = build.spares.poll();
        if (spare == null) spare = new Spare(new NodeStore(build.primitives), new KdTreeWriter(store.k));
        Spare other = spare;
        store.copyChild(d, 1, other.store);
        ForkJoinTask<Double> right = ForkJoinTask.adapt(() -> {
            other.out.clear();
            return recConst(build, other.store, d, 1, trials, other.out);
        }).fork();
        double cost = recConst(build, store, d, 0, trials, out);
        cost += right.join();
        out.setRightChild(interior);
        out.append(other.out);
        build.spares.push(other);
        return cost;
    }

    /** An idle store and writer for a subtree handed to another thread. */
    private record Spare(NodeStore store, KdTreeWriter out) {
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
    @Override public abstract String name();

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

    /**
     * {@return the root voxel a build over {@code primitives} starts from}: the bounds of them all
     * (a point at the origin for none); static and final, so that a checker may compute it on its own
     *
     * @param primitives the scene's primitives
     * @throws InvalidGeometryException naming the first primitive with non-finite or empty bounds
     */
    public static Box rootVoxel(Primitives primitives) {
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

    /** {@code round(8 + c log2 N)}, at most {@link #DEPTH_LIMIT}: pbrt's and Wald and Havran's cap with c = 1.3. */
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
    @Override public final int depthCap(int n) {
        int maxDepth = maxDepth();
        return maxDepth >= 0 ? maxDepth : automaticDepthCap(n, depthFactor);
    }

    // ---- settings ----

    /**
     * {@return the setting rows this builder takes}: Kt, Ki, Kmaxdepth, B, perfect splits and
     * threads. A subclass that takes more returns these and its own.
     */
    @Override public List<Setting<?>> settingRows() { return ROWS; }

    /** {@return this builder's settings, one immutable value} */
    @Override public final Settings settings() { return settings; }

    /**
     * Gives this builder {@code settings}, replacing the ones it had.
     *
     * @param settings the settings; each given row must be one of {@link #settingRows()}
     * @return this builder
     * @throws IllegalArgumentException naming every given row this builder does not take
     */
    @Override public final KdTreeBuilder configure(Settings settings) {
        this.settings = StructureBuilder.checkTakes(this, settings);
        this.costModel = SharedSettings.costModel(settings);
        return this;
    }

    /**
     * Gives this builder one row's value (its range checked once, by the row).
     *
     * @param row   a row this builder takes
     * @param value its value, or null for its default
     * @param <T>   its type
     * @return this builder
     */
    public final <T> KdTreeBuilder with(Setting<T> row, T value) {
        return configure(settings.with(row, value));
    }

    /** {@return Kmaxdepth, or -1 for the default {@code 8 + 1.3 log2 N}} */
    public final int maxDepth() { return settings.get(SharedSettings.MAX_DEPTH); }

    /**
     * Sets Kmaxdepth (0 .. 64), or -1 for the default {@code 8 + 1.3 log2 N}.
     *
     * @param depth Kmaxdepth, or -1
     * @return this builder
     */
    public final KdTreeBuilder maxDepth(int depth) { return with(SharedSettings.MAX_DEPTH, depth); }

    /** {@return c in the automatic depth cap {@code 8 + c log2 N}} (default 1.3), used when Kmaxdepth is not set. */
    public final double depthFactor() { return depthFactor; }

    /**
     * Sets c (0 .. 4) in the automatic depth cap {@code 8 + c log2 N}: a lower cap builds a
     * smaller tree faster at some cost in quality (the SAH's quality presets set it).
     * @param c the factor
     * @return this builder
     */
    public final KdTreeBuilder depthFactor(double c) {
        this.depthFactor = Limits.DEPTH_FACTOR.check(Limits.DEPTH_FACTOR.title(), c);
        return this;
    }

    /** {@return B, the references per input primitive the tree may hold at the most} ({@link ReferenceBudget}) */
    public final int referenceBudget() { return settings.get(REFERENCE_BUDGET); }

    /**
     * Sets B (1 .. 65,536): the tree holds at most B references per input primitive; where the
     * geometry would need more, nodes become leaves early and the tree says how many
     * ({@link KdTree#budgetLeaves()}).
     * @param perPrimitive B
     * @return this builder
     */
    public final KdTreeBuilder referenceBudget(int perPrimitive) { return with(REFERENCE_BUDGET, perPrimitive); }

    /** {@return Kt and Ki}: the SAH uses them to choose planes; every tree reports its expected cost with them. */
    public final CostModel costModel() { return costModel; }

    /**
     * Sets Kt and Ki (default: Wald and Havran's {@link CostModel#WALD_HAVRAN}): the rows
     * {@link SharedSettings#KT} and {@link SharedSettings#KI}.
     *
     * @param model Kt and Ki
     * @return this builder
     */
    public final KdTreeBuilder costModel(CostModel model) { return configure(SharedSettings.withCostModel(settings, model)); }

    /** {@return whether straddling primitives are clipped to each child voxel} (default: on). */
    public final boolean perfectSplits() { return settings.get(PERFECT_SPLITS); }

    /**
     * Turns perfect splits on (exact clipping, the default) or off (bounding boxes only).
     *
     * @param on true for perfect splits
     * @return this builder
     */
    public final KdTreeBuilder perfectSplits(boolean on) { return with(PERFECT_SPLITS, on); }

    /** {@return the number of threads a build uses} (default 1). */
    public final int threads() { return settings.get(SharedSettings.THREADS); }

    /**
     * Sets the number of threads (1 .. 256). With more than one, independent subtrees are built
     * in parallel (fork/join); the tree is the same as with one thread.
     * @param n the number of threads
     * @return this builder
     */
    public final KdTreeBuilder threads(int n) { return with(SharedSettings.THREADS, n); }

    /** {@return a one-line summary of the settings}, e.g. for the command line. */
    @Override public String describeSettings() {
        int maxDepth = maxDepth(), threads = threads(), budget = referenceBudget();
        return "maxDepth=" + (maxDepth >= 0 ? String.valueOf(maxDepth)
                : depthFactor == DEFAULT_DEPTH_FACTOR ? "auto" : "auto(8+" + depthFactor + " log2 N)") + " Kt=" + costModel.kt() + " Ki=" + costModel.ki()
                + " perfectSplits=" + perfectSplits() + (threads > 1 ? " threads=" + threads : "")
                + (budget != REFERENCE_BUDGET.defaultValue() ? " referenceBudget=" + budget : "");
    }

    /** The per-build context that {@link BuildContext} exposes to subclasses. */
    private record Build(Primitives primitives, int depthCap, int forkThreshold, BuildWatch watch, Deque<Spare> spares,
                         boolean perfectSplits)
            implements BuildContext {
    }
}
