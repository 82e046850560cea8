/**
 * The k-d tree itself: {@link org.kdtree.tree.KdTree} (immutable flat arrays), the writer
 * builders emit nodes into, statistics and the expected SAH cost, and the walker that visits
 * every node with its voxel. The node layout is {@link org.kdtree.tree.Nodes}'s alone: every
 * other package reads nodes through its accessors or {@code KdTree}'s methods.
 *
 * <p>Layer 2: it may use {@code limits} and {@code geom}.
 */
package org.kdtree.tree;
