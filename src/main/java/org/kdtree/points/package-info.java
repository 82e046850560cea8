/**
 * Point queries on trees over k-D points: k nearest neighbours (exact, best-bin-first, 1 +
 * eps), radius and box search, under any Minkowski metric; one query object per thread, results
 * into the caller's arrays.
 *
 * <p>Layer 6: it may use the packages of layers 1 to 5 (its default builder comes from
 * {@code build}).
 */
package org.kdtree.points;
