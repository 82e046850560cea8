/**
 * Bounding volume hierarchies beside the kd-trees: a binned-SAH build over primitive bounds
 * with the kd-tree's cost model ({@link org.kdtree.bvh.BvhBuilder}), the hierarchy in a binary
 * layout for reading and a collapsed wide one for tracing ({@link org.kdtree.bvh.Bvh}), and
 * their traversals, the same queries as a kd-tree's ({@link org.kdtree.accel.AccelerationStructure}).
 *
 * <p>Layer 4: it may use {@code limits}, {@code geom}, {@code shape} and {@code accel} (the queries, the listener,
 * the one triangle test, the cost model and statistics); never the kd-tree, its sibling. See docs/bvh.md.
 */
package org.kdtree.bvh;
