/**
 * Bounding volume hierarchies beside the kd-trees: a binned-SAH build over primitive bounds
 * with the kd-tree's cost model ({@link org.kdtree.bvh.BvhBuilder}), the hierarchy with its
 * layouts made when it is built ({@link org.kdtree.bvh.Bvh}: binary for reading, wide nodes and
 * leaf blocks for single rays, pairs for packets), and its three traversal loops, the same
 * queries as a kd-tree's ({@link org.kdtree.accel.AccelerationStructure}): the listening one, and
 * the single-ray and packet loops, each written once over narrow node and leaf kernels whose
 * Java 17 and Vector API implementations (the latter in src/vector/java) are picked once at
 * start-up ({@link org.kdtree.accel.Vectorization#kernel}).
 *
 * <p>Layer 4: it may use {@code limits}, {@code geom}, {@code shape} and {@code accel} (the queries, the listener,
 * the one triangle test, the cost model and statistics); never the kd-tree, its sibling. See docs/bvh.md.
 */
package org.kdtree.bvh;
