/**
 * Reading files, every error one line naming file, line and field: the one OBJ reader
 * ({@link org.kdtree.io.ObjMeshReader}, streaming into flat arrays), {@code .scene2d} 2-D
 * scenes, point CSV files, loading by extension, and JSON render scenes with OBJ/MTL into
 * {@code scene} types.
 *
 * <p>Layer 7: it may use the packages of layers 1 to 6; not {@code render}.
 */
package org.kdtree.io;
