package org.kdtree.kdtree;

import org.kdtree.accel.AccelerationStructure;
import org.kdtree.accel.CostModel;
import org.kdtree.accel.Hit;
import org.kdtree.accel.Intersector;
import org.kdtree.accel.PacketQuery;
import org.kdtree.accel.RayQuery;
import org.kdtree.accel.TraversalListener;
import org.kdtree.accel.TreeStats;
import org.kdtree.accel.TriangleIntersector;
import org.kdtree.accel.Vectorization;
import org.kdtree.geom.Box;
import org.kdtree.geom.Ray;
import org.kdtree.shape.Primitives;

/**
 * A built kd-tree: immutable flat arrays, in the spirit of pbrt's compact nodes.
 *
 * <p>Nodes are stored depth first, 12 bytes each in one {@code int} array, so that a node is one
 * load away (there is no second copy for the traversal); leaves index into one shared array of
 * primitive references. A node keeps its split position as the {@code double} the build
 * partitioned with (a float would move it off the primitive bounds the builder chose, see
 * docs/traversal.md). {@link Nodes} is the layout, and the only code that decodes it.
 *
 * <p>The methods below answer node by node. Hot paths decode the flat arrays with {@link Nodes}
 * and this tree's {@link #axisBits()} instead: the traversal reads them in place (this package),
 * the point queries a copy they keep ({@link #nodeArray()}, {@link #refArray()}); no method hands
 * out the tree's own arrays, so it is immutable.
 *
 * <p>As an {@link AccelerationStructure}, a sibling of the bounding volume hierarchy, its ray
 * queries are {@link Traverser}s.
 */
public final class KdTree implements AccelerationStructure {
    /** The most dimensions a tree may have ({@link org.kdtree.limits.Limits#DIMENSION}). */
    public static final int MAX_DIMENSION = (int) org.kdtree.limits.Limits.DIMENSION.max();

    private final Box bounds;
    private final CostModel cost;
    private final String builderName;
    /** The nodes, {@link Nodes}'s layout; read in place by this package's hot loops, never changed. */
    final int[] nodes;
    /** The leaves' primitive references, in leaf order; read in place by this package, never changed. */
    final int[] refs;
    private final int budgetLeaves;
    private final int axisBits;
    /** What it was built over; its ray tests are made from them once, on the first query. */
    private final Primitives primitives;
    private Intersector intersector;
    /**
     * A mesh's corners ({@link TriangleIntersector#corners}), made with the tree: its tracing layout,
     * read in place by the intersector, {@link MeshTraversal} and {@link PacketTraversal}; null for
     * other primitives. (A copy per reference in leaf order was measured: set R 0.92-0.95 x the
     * speed, four times the memory: docs/traversal.md.)
     */
    final double[] corners;
    private TreeStats stats;

    KdTree(Primitives primitives, Box bounds, CostModel cost, String builderName, int[] nodes, int[] refs, int budgetLeaves) {
        this.primitives = primitives;
        this.budgetLeaves = budgetLeaves;
        this.bounds = bounds;
        this.cost = cost;
        this.builderName = builderName;
        this.nodes = nodes;
        this.refs = refs;
        this.axisBits = Nodes.axisBits(bounds.dimension());
        corners = TriangleIntersector.cornersOf(primitives);
    }

    /**
     * A tree saved earlier, restored from its arrays over the primitives it was built over (a
     * saved tree's reader); the arrays are checked to make one tree before any query reads them.
     *
     * @param primitives  what it was built over (its fingerprint checked by the caller)
     * @param bounds      the root voxel
     * @param cost        the Kt and Ki of its expected cost
     * @param builderName the builder that made it
     * @param nodes       the nodes in {@link Nodes}'s layout, as {@link #nodeArray()} gave them (kept, not copied)
     * @param refs        the leaves' references, as {@link #refArray()} gave them (kept, not copied)
     * @param budgetLeaves the {@link #budgetLeaves()} of the saved tree
     * @param stated      the statistics saved with it, or null to count them on the first {@link #stats()}: every count
     *                    is checked against the arrays as they are checked, and the expected cost, which needs every
     *                    voxel's area, is taken as stated (a load stays linear in the file, without a walk of the voxels)
     * @return the tree
     * @throws IllegalArgumentException naming the first node, link or reference that does not make a tree over these
     *         primitives, or a stated count that is not the tree's
     */
    public static KdTree restore(Primitives primitives, Box bounds, CostModel cost, String builderName, int[] nodes, int[] refs,
                                 int budgetLeaves, TreeStats stated) {
        if (bounds.dimension() != primitives.dimension())
            throw new IllegalArgumentException("a " + bounds.dimension() + "-D root voxel over " + primitives.dimension() + "-D primitives");
        if (!bounds.isFinite() && primitives.size() > 0) throw new IllegalArgumentException("the root voxel " + bounds + " is not finite");
        if (budgetLeaves < 0) throw new IllegalArgumentException("a negative count of early leaves, " + budgetLeaves);
        RestoredLinks.Counts counts = RestoredLinks.check(nodes, refs, bounds, primitives.size());
        KdTree tree = new KdTree(primitives, bounds.copy(), cost, builderName, nodes, refs, budgetLeaves);
        if (stated != null) tree.stats = counts.confirm(stated, tree.memoryBytes());
        return tree;
    }

    /**
     * The ray tests of the primitives it was built over, made once, on the first query (points
     * have none: they throw then); a mesh's over the corners copied with the tree.
     */
    synchronized Intersector intersector() {
        if (intersector == null) intersector = Intersector.of(primitives, corners);
        return intersector;
    }

    /** {@return the width of the axis field of this tree's node words}: what {@link Nodes} decodes a word with */
    public int axisBits() { return axisBits; }

    /** {@return k, the dimension} */
    public int dimension() { return bounds.dimension(); }

    /**
     * Checks that a query's objects have this tree's dimension.
     *
     * @param dimension their dimension
     * @param what what they are, for the message ("primitives", "points")
     * @throws IllegalArgumentException naming both dimensions if they differ
     */
    public void requireDimension(int dimension, String what) {
        if (dimension != dimension())
            throw new IllegalArgumentException("tree is " + dimension() + "-D, " + what + " " + dimension + "-D");
    }

    /** {@return the root voxel (a copy)} */
    public Box bounds() { return bounds.copy(); }

    /** {@return the Kt and Ki used for {@link TreeStats#expectedCost()}} */
    @Override public CostModel costModel() { return cost; }

    /** {@return the name of the builder that made this tree} */
    public String builderName() { return builderName; }

    /** {@return the number of nodes, interior and leaf} */
    public int nodeCount() { return nodes.length / Nodes.INTS; }

    /**
     * Leaves the build made early because the reference budget ran out
     * ({@code KdTreeBuilder.referenceBudget}); 0 when the tree is the one the builder's own rules make.
     * @return the number of such early leaves
     */
    public int budgetLeaves() { return budgetLeaves; }

    // ---- node access (small enough to be inlined into hot loops) ----

    /**
     * {@return whether {@code node} is a leaf}
     * @param node a node index
     */
    public boolean isLeaf(int node) { return Nodes.isLeaf(Nodes.word(nodes, node), axisBits); }
    /**
     * {@return the split axis of interior node {@code node}}
     * @param node an interior node's index
     */
    public int axis(int node) { return Nodes.axis(Nodes.word(nodes, node), axisBits); }
    /**
     * {@return the split plane's position on the axis of interior node {@code node}}
     * @param node an interior node's index
     */
    public double split(int node) { return Nodes.split(nodes, node); }
    /**
     * {@return the left (lower) child of interior node {@code node}}
     * @param node an interior node's index
     */
    public int leftChild(int node) { return Nodes.leftChild(node); }
    /**
     * {@return the upper child of interior node {@code node}}
     * @param node an interior node's index
     */
    public int rightChild(int node) { return Nodes.rightChild(Nodes.word(nodes, node), axisBits); }
    /**
     * {@return where the references of leaf {@code node} begin in {@link #refArray()}}
     * @param node a leaf node's index
     */
    public int leafStart(int node) { return Nodes.leafStart(nodes, node); }
    /**
     * {@return where the references of leaf {@code node} end (exclusive) in {@link #refArray()}}
     * @param node a leaf node's index
     */
    public int leafEnd(int node) { return leafStart(node) + leafSize(node); }
    /**
     * {@return the number of primitive references in leaf {@code node}}
     * @param node a leaf node's index
     */
    public int leafSize(int node) { return Nodes.leafSize(Nodes.word(nodes, node), axisBits); }
    /**
     * {@return the i-th entry of the shared leaf reference array}
     * @param i an index into {@link #refArray()}
     */
    public int ref(int i) { return refs[i]; }

    /**
     * {@return a copy of the nodes, three ints each, as {@link Nodes} lays them out}: for another
     * package's flat hot loops (the point queries), which keep it
     */
    public int[] nodeArray() { return nodes.clone(); }
    /** {@return a copy of the shared leaf reference array (primitive indices), in leaf order} */
    public int[] refArray() { return refs.clone(); }

    /**
     * {@return the primitives referenced by a leaf node, as a new array}
     * @param node a leaf node's index
     */
    public int[] leafPrimitives(int node) {
        return java.util.Arrays.copyOfRange(refs, leafStart(node), leafEnd(node));
    }

    /**
     * Visits every node depth first, left child first, with its voxel and depth.
     *
     * @param visitor receives every interior node and leaf
     */
    public void walk(TreeVisitor visitor) {
        walk(0, 0, bounds.copy(), visitor);
    }

    private void walk(int node, int depth, Box voxel, TreeVisitor v) {
        if (isLeaf(node)) {
            v.leaf(node, depth, voxel, leafStart(node), leafEnd(node));
            return;
        }
        int axis = axis(node);
        double xi = split(node);
        v.interior(node, depth, voxel, axis, xi);
        double lo = voxel.min(axis), hi = voxel.max(axis);
        voxel.setMax(axis, xi);
        walk(leftChild(node), depth + 1, voxel, v);
        voxel.setMax(axis, hi).setMin(axis, xi);
        walk(rightChild(node), depth + 1, voxel, v);
        voxel.setMin(axis, lo);
    }

    /** {@return the tree's statistics (computed once)} */
    public TreeStats stats() {
        if (stats == null) stats = KdTreeStats.of(this);
        return stats;
    }

    /**
     * {@return bytes held by the arrays (12 per node, 4 per reference, plus the arrays' headers),
     * and over a mesh its tracing layout's (the triangles' corners: 72 per triangle)}
     */
    public long memoryBytes() {
        return 2 * 16L + 4L * nodes.length + 4L * refs.length + (corners == null ? 0 : 16 + 8L * corners.length);
    }

    /** {@return a line when the reference budget made leaves early ({@link #budgetLeaves()}), else none} */
    @Override public java.util.List<String> notes() {
        if (budgetLeaves == 0) return java.util.List.of();
        return java.util.List.of("the reference budget setting made " + budgetLeaves + (budgetLeaves == 1 ? " leaf" : " leaves")
                + " early");
    }

    /** {@return "kd-tree"} */
    @Override public String kind() { return "kd-tree"; }

    /** {@return a {@link Traverser} over this tree and the primitives it was built over} */
    @Override public RayQuery query() { return new Traverser(this); }

    /**
     * {@return a packet loop over this tree ({@link PacketTraversal}: Wald's coherent ray tracing,
     * one node read for all the packet's rays), its single rays through {@link #query()}'s fast loop}
     *
     * @throws IllegalArgumentException if it was not built over a 3-D triangle mesh
     */
    @Override public PacketQuery packetQuery() {
        if (corners == null || dimension() != 3)
            throw new IllegalArgumentException("packets are traced against a triangle mesh; this " + dimension() + "-D tree holds other primitives");
        return new PacketTraversal(this, query());
    }

    /**
     * {@return which kernels the packet loop runs}: the Vector API's or the Java 17 ones ({@link
     * PacketKernel}, chosen once per JVM), and that single rays take the scalar single-ray loop
     */
    @Override public String describePath() {
        PacketTraversal.vectorKernels();     // loads the kernel first: one that does not load turns the path scalar, with its reason
        return Vectorization.describe() + "; the packet loop's node and leaf kernels (set P in 8 x 8 packets), single rays scalar";
    }

    /** {@return a {@link Traverser} over this tree and its primitives that reports every step to {@code listener}} */
    @Override public RayQuery query(TraversalListener listener) {
        Traverser t = new Traverser(this);
        return new RayQuery() {
            @Override public boolean closestHit(Ray ray, double tMin, double tMax, Hit hit) {
                return t.closestHit(ray, tMin, tMax, hit, listener);
            }

            @Override public boolean anyHit(Ray ray, double tMin, double tMax) {
                return t.anyHit(ray, tMin, tMax, listener);
            }
        };
    }
}
