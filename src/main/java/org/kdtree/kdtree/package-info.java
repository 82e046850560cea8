/**
 * The kd-tree, built, stored and traversed, in one package so that its arrays stay its own.
 * Building: {@link org.kdtree.kdtree.KdTreeBuilder} (the talk's Algorithm 1, written once for
 * every builder; subclasses decide {@code terminate} and {@code findPlane}) over one node store,
 * viewed as {@link org.kdtree.kdtree.BuildNode}; its partition step; the median-plane,
 * object-median, sliding-midpoint and SAH builders with the SAH's plane searches;
 * {@link org.kdtree.kdtree.Supervisor}, which runs an untrusted (a student's) builder on a thread
 * of its own within deadlines and names its faults ({@link org.kdtree.kdtree.BuilderFault}).
 * The tree: {@link org.kdtree.kdtree.KdTree} (immutable flat arrays), the writer builders emit
 * nodes into, the walker, and the node layout, which is {@link org.kdtree.kdtree.Nodes}'s alone.
 * Traversal: the Havran-style stack traversal ({@link org.kdtree.kdtree.Traverser}), closest,
 * any and all hits, with a listening loop and a silent one.
 *
 * <p>Layer 4: it may use {@code limits}, {@code geom}, {@code shape} and {@code accel}; never the
 * bounding volume hierarchy, its sibling, nor any package above it, so a builder of a student's
 * jar joins without a change here.
 */
package org.kdtree.kdtree;
