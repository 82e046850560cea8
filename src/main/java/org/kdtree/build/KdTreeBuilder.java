package org.kdtree.build;

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
 * The talk's Algorithm 1, written once:
 * <pre>
 * recConst(T, V):
 *   if terminate(T, V): return Leaf(T)
 *   p = findPlane(T, V)
 *   (V_L, V_R) = cut V with p
 *   T_L = { t in T | t overlaps V_L },  T_R = { t in T | t overlaps V_R }
 *   return Node(p, recConst(T_L, V_L), recConst(T_R, V_R))
 * </pre>
 * Subclasses decide {@link #terminate} and {@link #findPlane}; they may override
 * {@link #split}; a subclass with an engine of its own that builds the same tree may override
 * {@link #construct} (the SAH's event and binned engines do).
 *
 * <p>Three safety nets stand around the subclass's decisions, so that no input can make a
 * build run away: the recursion never goes deeper than {@link #maxDepth()} (default
 * {@code 8 + 1.3 log2 N}); a split that sends every primitive to both children (it separates
 * nothing, as with thousands of coincident triangles) makes a leaf instead; and so does a split
 * whose children would exceed the node's share of the {@link #referenceBudget()}.
 *
 * <p>A builder is configured before use and may be reused; {@link #build} is safe to call
 * from several threads only if the subclass keeps no per-build state in fields.
 */
public abstract class KdTreeBuilder {
    /** Depth beyond which no setting can go: 2^64 voxels would not fit in any memory ({@link Limits#MAX_DEPTH}). */
    public static final int DEPTH_LIMIT = (int) Limits.MAX_DEPTH.max();

    /** B, the references per input primitive a tree may hold at the most ({@link ReferenceBudget}). */
    public static final int DEFAULT_REFERENCE_BUDGET = 256;

    /** c in the automatic depth cap {@code 8 + c log2 N} (pbrt's and Wald and Havran's 1.3). */
    public static final double DEFAULT_DEPTH_FACTOR = 1.3;

    private int maxDepth = -1;
    private double depthFactor = DEFAULT_DEPTH_FACTOR;
    private int referenceBudget = DEFAULT_REFERENCE_BUDGET;
    private CostModel costModel = CostModel.WALD_HAVRAN;
    private boolean perfectSplits = true;
    private int threads = 1;

    /**
     * Builds the tree of {@code primitives}, starting from their bounding box (constKdTree).
     *
     * @throws java.util.concurrent.CancellationException if the calling thread is interrupted
     *         during the build (the build stops at its next split)
     * @param primitives the scene's primitives
     * @return the tree
     */
    public final KdTree build(Primitives primitives) {
        return build(primitives, BuildWatch.unwatched());
    }

    /** {@link #build(Primitives)} under {@code watch}: a supervisor's view of the build, and its way to stop it. */
    final KdTree build(Primitives primitives, BuildWatch watch) {
        Box rootVoxel = rootVoxel(primitives);
        int depthCap = depthCap(primitives.size());
        KdTreeWriter out = new KdTreeWriter(primitives.dimension());
        Build build = new Build(primitives, depthCap, threads == 1 ? Integer.MAX_VALUE : forkThreshold(primitives.size(), threads),
                watch);
        if (threads == 1) {
            construct(build, rootVoxel, out);
        } else {
            ForkJoinPool pool = new ForkJoinPool(threads);
            try {
                pool.invoke(ForkJoinTask.adapt(() -> construct(build, rootVoxel, out)));
            } finally {
                pool.shutdown();
            }
        }
        return out.finish(rootVoxel, costModel, name());
    }

    /**
     * Writes the tree of {@code context}'s primitives in {@code rootVoxel} into {@code out}: by
     * default Algorithm 1 below. A subclass with an engine of its own (the SAH's event engine)
     * overrides this, and must write the very tree the recursion would. Runs inside the build's
     * fork/join pool when {@link #threads()} is above 1.
     * @param context the build's primitives, depth cap and fork threshold
     * @param rootVoxel the scene box, the root's voxel
     * @param out receives the nodes depth first
     */
    protected void construct(BuildContext context, Box rootVoxel, KdTreeWriter out) {
        Build build = (Build) context;
        BuildNode root = makeRoot(build, rootVoxel);
        root.budget(ReferenceBudget.root(referenceBudget, root.size()));
        recConst(build, root, out);
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

    /**
     * Cuts the node's voxel with {@code plane} and sends each primitive to every child voxel it
     * overlaps. A primitive whose part in the voxel ends at the plane goes to that side only; one
     * lying in the plane goes to the side {@link SplitPlane#planarLeft()} names; one crossing the
     * plane goes to both, with its bounds clipped to each child ("perfect splits", unless turned
     * off, in which case the child keeps the box of the parent's bounds cut by the plane).
     * @param context the build in progress
     * @param node the node to split
     * @param plane the split plane, strictly inside the node's voxel
     * @return the two children with their references
     */
    protected Children split(BuildContext context, BuildNode node, SplitPlane plane) {
        return Partition.split(context, node, plane, perfectSplits);
    }

    /**
     * Makes the root node: every primitive with its own bounds, in the scene's box.
     *
     * @param context the build in progress
     * @param rootVoxel the scene box
     * @return the root node
     */
    protected BuildNode makeRoot(BuildContext context, Box rootVoxel) {
        Primitives primitives = context.primitives();
        int n = primitives.size(), k = primitives.dimension();
        int[] refs = new int[n];
        double[] clipped = new double[2 * k * n];
        for (int i = 0; i < n; i++) refs[i] = i;
        Partition.writeAllBounds(primitives, clipped);
        return new BuildNode(rootVoxel, refs, clipped, 0);
    }

    private void recConst(Build build, BuildNode node, KdTreeWriter out) {
        build.watch.node(node.depth(), node.size());
        if (node.depth() >= build.depthCap || callTerminate(build, node)) {
            out.leaf(node.refArray(), node.base(), node.size());
            return;
        }
        SplitPlane plane = checked(callFindPlane(build, node), node);
        Children children = split(build, node, plane);
        int nl = children.left().size(), nr = children.right().size();
        int outcome = SplitOutcome.of(node.size(), nl, nr, node.budget());
        if (outcome != SplitOutcome.SPLIT) {
            if (outcome == SplitOutcome.OVER_BUDGET) out.budgetLeaf();
            out.leaf(node.refArray(), node.base(), node.size());
            return;
        }
        children.left().budget(ReferenceBudget.share(node.budget(), nl, nl, nr));
        children.right().budget(ReferenceBudget.share(node.budget(), nr, nl, nr));
        node.release();
        int interior = out.interior(plane.axis(), plane.position());
        if (children.right().size() >= build.forkThreshold && children.left().size() > 0) {
            // The right subtree is built by another thread into its own writer, then spliced in:
            // the same recursion, so the same tree, in the same depth-first order.
            BuildNode rightChild = children.right();
            ForkJoinTask<KdTreeWriter> right = ForkJoinTask.adapt(() -> {
                KdTreeWriter w = new KdTreeWriter(node.dimension());
                recConst(build, rightChild, w);
                return w;
            }).fork();
            recConst(build, children.left(), out);
            KdTreeWriter rightTree = right.join();
            out.setRightChild(interior);
            out.append(rightTree);
            return;
        }
        recConst(build, children.left(), out);
        out.setRightChild(interior);
        recConst(build, children.right(), out);
    }

    /** terminate, with whatever it throws named as this builder's fault. */
    private boolean callTerminate(Build build, BuildNode node) {
        build.watch.enter(BuildWatch.TERMINATE, node.depth(), node.size());
        try {
            return terminate(build, node);
        } catch (RuntimeException | Error e) {
            throw BuilderFaults.threw(this, BuilderFault.TERMINATE, node, e);
        } finally {
            build.watch.leave();
        }
    }

    /** findPlane, with whatever it throws named as this builder's fault. */
    private SplitPlane callFindPlane(Build build, BuildNode node) {
        build.watch.enter(BuildWatch.FIND_PLANE, node.depth(), node.size());
        try {
            return findPlane(build, node);
        } catch (RuntimeException | Error e) {
            throw BuilderFaults.threw(this, BuilderFault.FIND_PLANE, node, e);
        } finally {
            build.watch.leave();
        }
    }

    /** The plane findPlane returned, if the recursion can use it; else this builder's fault. */
    private SplitPlane checked(SplitPlane p, BuildNode node) {
        if (p == null) throw BuilderFaults.badPlane(this, node, "returned null",
                "return a plane for every node that terminate does not make a leaf");
        if (p.axis() >= node.dimension()) throw BuilderFaults.badPlane(this, node, "chose axis " + p.axis() + " in "
                + node.dimension() + "-D", "the axis must be 0 .. " + (node.dimension() - 1));
        Box v = node.voxel();
        if (p.position() < v.min(p.axis()) || p.position() > v.max(p.axis()))
            throw BuilderFaults.badPlane(this, node, "chose x" + p.axis() + " = " + p.position() + ", outside the voxel " + v,
                    "findPlane must return a plane on one of the node's axes, inside its voxel");
        return p;
    }

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
    public int depthCap(int n) {
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
     * {@return B, the references per input primitive the tree may hold at the most} (default 256; {@link ReferenceBudget}).
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
     * Sets Kt and Ki (default 15 and 20).
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

    /** {@return whether straddling primitives are clipped to each child voxel} (default true). */
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

    /** {@return the number of threads a build uses} (default 1). */
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
                + (referenceBudget != DEFAULT_REFERENCE_BUDGET ? " referenceBudget=" + referenceBudget : "");
    }

    /** The per-build context that {@link BuildContext} exposes to subclasses. */
    private record Build(Primitives primitives, int depthCap, int forkThreshold, BuildWatch watch) implements BuildContext {
    }
}
