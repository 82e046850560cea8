/**
 * The primitives a builder sees ({@link org.kdtree.shape.Primitives}: bounds and clipped
 * bounds, nothing of rays): 3-D triangle meshes in flat arrays, 2-D shapes, k-D points (the
 * generated scenes are {@code generate}'s).
 *
 * <p>Layer 2: it may use {@code limits} and {@code geom}.
 */
package org.kdtree.shape;
