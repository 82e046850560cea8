/**
 * What a render is of: camera, lights, materials, and the scene's triangles with a material and
 * normals each ({@link org.kdtree.scene.SceneGeometry}, collected by
 * {@link org.kdtree.scene.GeometryBuilder} from the built-in shapes'
 * {@link org.kdtree.scene.Tessellation} or a file's mesh). {@link org.kdtree.scene.Vec3}
 * describes positions and colours; {@link org.kdtree.scene.Vectors} is the tracer's
 * allocation-free arithmetic on arrays.
 *
 * <p>Layer 6: it may use {@code limits}, {@code geom} and {@code shape}. {@code io} fills it
 * and {@code render} reads it, and neither of those two knows the other.
 */
package org.kdtree.scene;
