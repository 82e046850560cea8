/**
 * Comparing data through their kd-trees (the talk's section 5.2, after Kubica et al.'s indexing
 * of asteroid images by their kd-tree transforms): a tree's {@link org.kdtree.compare.TreeSignature}
 * (where its large and small voxels are, where its split planes lie, how deep its leaves go, and a
 * picture of its leaves' depths on a common grid), normalised to its root box so that translation
 * and uniform scale do not matter, and a {@link org.kdtree.compare.TreeDistance} between two
 * signatures in [0, 1], term by term ({@link org.kdtree.compare.Term}).
 *
 * <p>Layer 6: it may use the packages of layers 1 to 5 (it reads trees of {@code kdtree}).
 */
package org.kdtree.compare;
