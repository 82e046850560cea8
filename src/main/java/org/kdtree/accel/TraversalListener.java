package org.kdtree.accel;

/**
 * Watches one ray's traversal step by step: the hook for the workbench's traversal stepper and
 * for per-ray statistics ({@link TraversalStats} is a listener that counts).
 *
 * <p>Events arrive in this order for a query (the kd-tree's {@code Traverser.closestHit(ray,
 * tMin, tMax, hit, listener)} and its siblings):
 * <ol>
 * <li>{@link #begin}: the ray's interval clipped to the scene box (or {@link #missedScene} and
 * then {@link #end}, when the ray misses the box);</li>
 * <li>for each interior node on the way down, {@link #interior} with the node's interval
 * {@code [tMin, tMax]}, {@code tSplit}, the near and far children, and which of them the ray
 * visits; when it visits both, {@link #pushFar} follows (the far child, saved for later, with its
 * interval);</li>
 * <li>at a leaf, {@link #leaf}, then {@link #primitive} for each primitive tested (primitives
 * already tested for this ray are skipped: mailboxing, reported by {@link #mailboxed});</li>
 * <li>after a leaf, {@link #pop} for each saved far child taken from the stack, with
 * {@code skipped = true} when it cannot hold anything closer than the hit found so far;</li>
 * <li>{@link #end} with the final result.</li>
 * </ol>
 * A bounding volume hierarchy's traversal ({@code org.kdtree.bvh}) reports {@link #boxTest} for
 * each child box it tests and {@link #boxNode} for each interior node it enters, in place of
 * {@link #interior}; {@link #leaf}, {@link #primitive}, {@link #pop} and {@link #end} mean the same.
 * To replay a traversal, record the events into a list (they carry plain values, so a recorder
 * can copy them) and step through it. Methods default to doing nothing; listeners must not
 * modify the hit they are given.
 */
public interface TraversalListener {
    /** Which children of an interior node the ray visits. */
    enum Visit {
        /** Only the near child: the ray leaves the node before reaching the split plane. */
        NEAR,
        /** Only the far child: the ray reaches the split plane before entering the node. */
        FAR,
        /** Near child on {@code [tMin, tSplit]}, then far child on {@code [tSplit, tMax]}. */
        BOTH,
        /** The ray lies in the split plane: both children, each on the whole {@code [tMin, tMax]}. */
        BOTH_IN_PLANE
    }

    /** A listener that ignores everything. */
    TraversalListener NONE = new TraversalListener() { };

    /**
     * The ray enters the scene box over {@code [tMin, tMax]} (already clipped to the caller's range).
     *
     * @param tMin where the ray enters the scene box
     * @param tMax where it leaves
     */
    default void begin(double tMin, double tMax) { }

    /** The ray misses the scene box (or the caller's range is empty): nothing is visited. */
    default void missedScene() { }

    /**
     * An interior node: its split plane, the ray's interval in it, and the decision taken.
     *
     * @param node the interior node's index
     * @param axis its split axis
     * @param split its split plane's position
     * @param tMin where the ray enters the node's voxel
     * @param tMax where it leaves
     * @param tSplit where it meets the split plane
     * @param near the near child, the one the ray enters first
     * @param far the far child
     * @param visit which of them the ray visits
     */
    default void interior(int node, int axis, double split, double tMin, double tMax, double tSplit,
                          int near, int far, Visit visit) { }

    /**
     * A bounding volume hierarchy's child box was tested against the ray: entered over
     * {@code [tMin, tMax]}, or missed (then the interval is empty or lies beyond the closest hit).
     *
     * @param node    the child's index
     * @param entered whether the ray enters the box within its interval
     * @param tMin    where the ray enters the box
     * @param tMax    where it leaves
     */
    default void boxTest(int node, boolean entered, double tMin, double tMax) { }

    /**
     * A bounding volume hierarchy's interior node is visited over {@code [tMin, tMax]}: its
     * children's boxes are tested next.
     *
     * @param node the node's index
     * @param tMin where the ray enters its box
     * @param tMax where it leaves
     */
    default void boxNode(int node, double tMin, double tMax) { }

    /**
     * The far child is saved on the stack, to be visited over {@code [tMin, tMax]}.
     *
     * @param node the far child's index
     * @param tMin where the ray enters it
     * @param tMax where it leaves
     */
    default void pushFar(int node, double tMin, double tMax) { }

    /**
     * A saved node is taken from the stack; {@code skipped} when it lies beyond the closest hit.
     *
     * @param node the saved node's index
     * @param tMin where the ray enters it
     * @param tMax where it leaves
     * @param skipped whether it is dropped as lying beyond the closest hit
     */
    default void pop(int node, double tMin, double tMax, boolean skipped) { }

    /**
     * A leaf with {@code count} primitive references, visited over {@code [tMin, tMax]}.
     *
     * @param node the leaf's index
     * @param tMin where the ray enters the leaf
     * @param tMax where it leaves
     * @param count the number of primitive references
     */
    default void leaf(int node, double tMin, double tMax, int count) { }

    /**
     * A primitive was tested; {@code hit} with its t when it was hit (NaN otherwise).
     *
     * @param primitive the primitive's index
     * @param hit whether the ray hit it
     * @param t the hit's parameter, or NaN
     */
    default void primitive(int primitive, boolean hit, double t) { }

    /**
     * A primitive referenced again in this leaf was not tested again (mailboxing).
     *
     * @param primitive the primitive's index
     */
    default void mailboxed(int primitive) { }

    /**
     * The query is over; {@code hit} holds the result of a closest-hit query (none for others).
     *
     * @param found whether the query found a hit
     * @param hit the closest hit, for a closest-hit query
     */
    default void end(boolean found, Hit hit) { }
}
