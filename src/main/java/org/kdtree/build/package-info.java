/**
 * Building trees: {@link org.kdtree.build.KdTreeBuilder} (the talk's Algorithm 1, written once
 * for every builder; subclasses decide {@code terminate} and {@code findPlane}) over one node
 * store, viewed as {@link org.kdtree.build.BuildNode}; its partition step; the median-plane,
 * object-median, sliding-midpoint and SAH builders with the SAH's plane searches; a builder's
 * faults ({@link org.kdtree.build.BuilderFault}); and {@link org.kdtree.build.Builders}, which
 * finds every builder on the class path through {@link java.util.ServiceLoader}.
 *
 * <p>Layer 3: it may use {@code limits}, {@code geom}, {@code shape} and {@code tree}; never a
 * package above it, so a builder of a student's jar joins without a change here.
 */
package org.kdtree.build;
