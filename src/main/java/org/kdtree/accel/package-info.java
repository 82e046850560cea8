/**
 * What every acceleration structure shares, below all of them: the structure as a ray tracer
 * sees it ({@link org.kdtree.accel.AccelerationStructure}) and its queries
 * ({@link org.kdtree.accel.RayQuery}, {@link org.kdtree.accel.Hit}); the primitives' ray tests
 * ({@link org.kdtree.accel.Intersector}: watertight triangles, 2-D shapes) and brute force, the
 * oracle; the listener that hears each step of a traversal and the per-ray statistics; the cost
 * model (Kt, Ki) and a built structure's statistics; the one slab clip of a ray against a box.
 * The kd-tree ({@code kdtree}) and the bounding volume hierarchy ({@code bvh}) are built on it as
 * siblings; nothing here knows either.
 *
 * <p>Layer 3: it may use {@code limits}, {@code geom} and {@code shape}.
 */
package org.kdtree.accel;
