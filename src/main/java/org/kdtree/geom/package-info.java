/**
 * Geometry in k dimensions: boxes (voxels), rays, split planes, exact clipping of triangles and
 * segments to boxes ("perfect splits"), and {@link org.kdtree.geom.Tolerance}, the one home of
 * every numeric tolerance with the reason for its value.
 *
 * <p>Layer 1: it uses no other package of the library.
 */
package org.kdtree.geom;
