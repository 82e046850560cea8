package org.kdtree.bvh;

import java.util.Objects;
import org.kdtree.accel.AccelerationStructure;
import org.kdtree.accel.CostModel;
import org.kdtree.accel.Intersector;
import org.kdtree.accel.PacketQuery;
import org.kdtree.accel.RayQuery;
import org.kdtree.accel.TraversalListener;
import org.kdtree.accel.TreeStats;
import org.kdtree.accel.TriangleIntersector;
import org.kdtree.accel.Vectorization;
import org.kdtree.geom.Box;
import org.kdtree.shape.Primitives;

/**
 * A bounding volume hierarchy in flat arrays, with its layouts made when it is built:
 * <ul>
 * <li>the binary tree, for reading (the workbench, the listening traversal): node 0 is the root,
 * an interior node has {@link #left} and {@link #right}, a leaf a stretch of {@link #primitive}s;
 * each node's box bounds its primitives whole (a primitive is in exactly one leaf);</li>
 * <li>for single rays, the tree collapsed to {@link #width()} children per node ({@link WideNodes};
 * on the vector path, the node kernel's lanes), and over a mesh the leaves' triangles in blocks
 * ({@link LeafBlocks});</li>
 * <li>for packets, over a mesh, the wide layout at width 2 ({@link #pairs}) and the triangles'
 * corners in leaf order ({@link #leafCorners}).</li>
 * </ul>
 * None changes once built; all are counted in {@link #memoryBytes}. Sibling boxes may overlap
 * and need not cover the scene, so a traversal visits children by their entry distance and stops
 * at none before its closest hit.
 */
public final class Bvh implements AccelerationStructure {
    private final int k;
    /** Per binary node, k minima then k maxima. */
    private final double[] box;
    /** Per binary node: an interior node's left child (its right one follows), or {@code ~first} for a leaf. */
    private final int[] link;
    /** Per binary node: a leaf's primitive count, 0 for an interior node. */
    private final int[] size;
    /** The primitives in leaf order. */
    private final int[] primitives;
    private final int maxDepth;
    private final CostModel costModel;
    private TreeStats stats;
    private final Intersector intersector;
    /** The width it was built with ({@code --bvh-width}). */
    private final int width;
    /** The tracing layouts (the last three null unless over a mesh). */
    private final WideNodes wide;
    private final LeafBlocks leafBlocks;
    private final WideNodes pairs;
    private final double[] leafCorners;

    private Bvh(Primitives built, double[] box, int[] link, int[] size, int[] primitives, CostModel costModel, int width, int maxDepth) {
        this.k = built.dimension();
        this.box = box;
        this.link = link;
        this.size = size;
        this.primitives = primitives;
        this.costModel = costModel;
        this.maxDepth = maxDepth;
        double[] corners = TriangleIntersector.cornersOf(built);
        this.intersector = Intersector.of(built, corners);
        this.leafCorners = corners == null ? null : inLeafOrder(corners);
        this.width = width;
        this.wide = new WideNodes(this, WideTraversal.KERNEL.width(width));
        this.leafBlocks = corners == null ? null : new LeafBlocks(this, leafCorners, WideTraversal.KERNEL.blockWidth());
        this.pairs = corners == null ? null : wide.width == 2 ? wide : new WideNodes(this, 2);
    }

    /** The triangles' corners ({@link TriangleIntersector#corners}) copied into leaf order. */
    private double[] inLeafOrder(double[] corners) {
        double[] c = new double[9 * primitives.length];
        for (int r = 0; r < primitives.length; r++) System.arraycopy(corners, 9 * primitives[r], c, 9 * r, 9);
        return c;
    }

    /**
     * A hierarchy saved earlier, restored from its binary layout (checked to make one tree before
     * any query reads it); its tracing layouts are made as a build makes them.
     *
     * @param built      what it was built over (its fingerprint checked by the caller)
     * @param box        per node, k minima then k maxima, as {@link #min} and {@link #max} give them (kept, not copied)
     * @param link       per node, an interior node's left child ({@link #left}) or {@code ~}{@link #leafStart} of a leaf (kept)
     * @param size       per node, a leaf's {@link #leafSize}, 0 for an interior node (kept)
     * @param primitives the primitives in leaf order, as {@link #primitive} gives them (kept)
     * @param costModel  Kt and Ki it was built with
     * @param width      children per node of the wide layout ({@link #width()})
     * @return the hierarchy
     * @throws IllegalArgumentException naming the first node, link or primitive that does not make a tree over these primitives
     */
    public static Bvh restore(Primitives built, double[] box, int[] link, int[] size, int[] primitives, CostModel costModel, int width) {
        org.kdtree.limits.Limits.BVH_WIDTH.check("the width", width);
        int depth = RestoredLinks.check(built, box, link, size, primitives);
        return new Bvh(built, box, link, size, primitives, costModel, width, depth);
    }

    static Bvh of(Primitives built, BuildNode root, int[] primitives, BvhBuilder settings) {
        int k = built.dimension(), nodes = root.size();
        double[] box = new double[2 * k * nodes];
        int[] link = new int[nodes], size = new int[nodes];
        int depth = layOut(root, 0, 1, 0, k, box, link, size);
        return new Bvh(built, box, link, size, primitives, settings.costModel(), settings.width(), depth);
    }

    /** Writes {@code n} at {@code index}, its children at {@code next}; returns the subtree's depth. */
    private static int layOut(BuildNode n, int index, int next, int depth, int k, double[] box, int[] link, int[] size) {
        System.arraycopy(n.box, 0, box, 2 * k * index, 2 * k);
        if (n.isLeaf()) {
            link[index] = ~n.first;
            size[index] = n.count;
            return depth;
        }
        link[index] = next;
        // The left child's descendants come first, after the pair; the right child's follow them.
        int dl = layOut(n.left, next, next + 2, depth + 1, k, box, link, size);
        int dr = layOut(n.right, next + 1, next + 1 + n.left.size(), depth + 1, k, box, link, size);
        return Math.max(dl, dr);
    }

    @Override public String kind() { return BvhBuilder.NAME; }
    @Override public int dimension() { return k; }

    @Override public Box bounds() { return nodeBounds(0); }

    /** {@return the number of nodes of the binary tree} */
    public int nodeCount() { return link.length; }

    /**
     * {@return the children per node it was built with ({@code --bvh-width})}: the width of the
     * single rays' layout on the Java 17 path; on the vector path that layout has the node
     * kernel's lanes ({@link #describePath} says which)
     */
    public int width() { return width; }

    /** {@return the depth of the deepest leaf of the binary tree (the root's is 0)} */
    public int maxDepth() { return maxDepth; }

    /** {@return which kernels the fast loops run (Vector API or Java 17), the single rays' node width, and set P in 8 x 8 packets} */
    @Override public String describePath() {
        String lanes = wide.width == width ? "" : " (the vector lanes; --bvh-width " + width + " holds on the Java 17 path)";
        return Vectorization.describe() + "; single rays over " + wide.width + "-wide nodes" + lanes + "; set P in 8 x 8 packets over the binary tree";
    }

    /** {@return Kt and Ki, with which it was built and its expected cost is counted} */
    @Override public CostModel costModel() { return costModel; }

    /**
     * {@return whether {@code node} is a leaf}
     * @param node a node of the binary tree
     */
    public boolean isLeaf(int node) { return link[node] < 0; }

    /**
     * {@return the left child of an interior node}
     * @param node an interior node
     */
    public int left(int node) { return link[node]; }

    /**
     * {@return the right child of an interior node}
     * @param node an interior node
     */
    public int right(int node) { return link[node] + 1; }

    /**
     * {@return where a leaf's primitives start in the leaf order ({@link #primitive})}
     * @param node a leaf
     */
    public int leafStart(int node) { return ~link[node]; }

    /**
     * {@return how many primitives a leaf holds}
     * @param node a leaf
     */
    public int leafSize(int node) { return size[node]; }

    /**
     * {@return the primitive at position {@code r} of the leaf order}
     * @param r a position from {@link #leafStart} on
     */
    public int primitive(int r) { return primitives[r]; }

    /** {@return how many primitives it holds} (those of empty bounds are left out) */
    public int primitiveCount() { return primitives.length; }

    /**
     * {@return a node's box: min on {@code axis}}
     * @param node a node
     * @param axis an axis
     */
    public double min(int node, int axis) { return box[2 * k * node + axis]; }

    /**
     * {@return a node's box: max on {@code axis}}
     * @param node a node
     * @param axis an axis
     */
    public double max(int node, int axis) { return box[2 * k * node + k + axis]; }

    /**
     * {@return a node's box, as a new box}
     *
     * @param node a node
     */
    public Box nodeBounds(int node) {
        Box b = new Box(k);
        for (int a = 0; a < k; a++) b.setMin(a, min(node, a)).setMax(a, max(node, a));
        return b;
    }

    /** The layouts and the ray tests, for the traversals of this package (the mesh's layouts null over other primitives). */
    double[] boxArray() { return box; }
    int[] linkArray() { return link; }
    int[] primitiveArray() { return primitives; }
    WideNodes wide() { return wide; }
    LeafBlocks leafBlocks() { return leafBlocks; }
    WideNodes pairs() { return pairs; }
    Intersector intersector() { return intersector; }
    /** The triangles' corners, 9 per triangle, in leaf order: a leaf's triangles in one stretch of memory. */
    double[] leafCorners() { return leafCorners; }

    /**
     * {@return the bytes its arrays hold}: the binary tree and the tracing layouts (wide nodes, leaf
     * blocks, the packets' nodes, corners in leaf order), not the primitives' own ray tests
     */
    public long memoryBytes() {
        long mesh = leafCorners == null ? 0 : 8L * leafCorners.length + leafBlocks.memoryBytes() + (pairs == wide ? 0 : pairs.memoryBytes());
        return 8L * box.length + 4L * (link.length + size.length + primitives.length) + wide.memoryBytes() + mesh;
    }

    @Override public synchronized TreeStats stats() {
        if (stats == null) stats = BvhStats.of(this);
        return stats;
    }

    /**
     * The fastest query: over a triangle mesh, the packet loop ({@link PacketTraversal}), which
     * traces single rays with the single-ray loop ({@link WideTraversal}), both over the kernels
     * this JVM chose ({@link org.kdtree.accel.Vectorization#kernel}); otherwise the listening loop
     * over the binary tree, with any {@link Intersector}.
     */
    @Override public RayQuery query() {
        if (intersector instanceof TriangleIntersector) return packetQuery();
        return new BvhTraverser(this, TraversalListener.NONE);
    }

    /**
     * {@return its packet loop} ({@link PacketTraversal}, over the binary tree at width 2 and the
     * kernels this JVM chose), with the single-ray loop for the rays it leaves out
     *
     * @throws IllegalArgumentException if it was not built over a 3-D triangle mesh
     */
    @Override public PacketQuery packetQuery() {
        if (!(intersector instanceof TriangleIntersector))
            throw new IllegalArgumentException("packets are traced against a triangle mesh; this " + k + "-D hierarchy holds other primitives");
        return new PacketTraversal(this, new WideTraversal(this));
    }

    @Override public RayQuery query(TraversalListener listener) {
        return new BvhTraverser(this, Objects.requireNonNull(listener, "listener"));
    }
}
