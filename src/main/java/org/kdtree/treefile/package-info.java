/**
 * Saved trees: a built kd-tree or bounding volume hierarchy written to a file and read back in
 * milliseconds, refused whenever the file does not match (docs/tree-files.md). One writer
 * ({@code TreeFileWriter}), one reader ({@code TreeFileReader}), one layout ({@code TreeFormat}),
 * behind one door, {@link org.kdtree.treefile.TreeFile}; the file names the builder and its
 * settings through the one builder specification ({@link org.kdtree.spec.BuilderSpec}), and the
 * primitives by a fingerprint ({@code Fingerprint}), which must match the scene it is loaded over.
 *
 * <p>Layer 6 of docs/architecture.md: it may use {@code limits}, {@code geom}, {@code files},
 * {@code shape}, {@code accel}, {@code kdtree}, {@code bvh} and {@code spec}.
 */
package org.kdtree.treefile;
