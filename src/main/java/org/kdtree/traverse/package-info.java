/**
 * Ray queries on a tree: the intersectors (watertight triangles, 2-D shapes), brute force (the
 * oracle), and the stack traversal ({@link org.kdtree.traverse.Traverser}), closest hit, any
 * hit and all hits, optionally reporting each step to a listener.
 *
 * <p>Layer 3: it may use {@code limits}, {@code geom}, {@code shape} and {@code tree}.
 */
package org.kdtree.traverse;
