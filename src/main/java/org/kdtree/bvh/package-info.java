/**
 * Bounding volume hierarchies beside the kd-trees: a binned-SAH build over primitive bounds
 * with the kd-tree's cost model ({@link org.kdtree.bvh.BvhBuilder}), the hierarchy in a binary
 * layout for reading and a collapsed wide one for tracing ({@link org.kdtree.bvh.Bvh}), and
 * their traversals, the same queries as a kd-tree's ({@link org.kdtree.traverse.AccelerationStructure}).
 * <p>Layer 4: it may use {@code limits}, {@code geom}, {@code shape}, {@code tree} (the cost model and statistics)
 * and {@code traverse} (the queries, the listener and the one triangle test). See docs/bvh.md.
 */
package org.kdtree.bvh;
