/**
 * Building trees: {@link org.kdtree.build.KdTreeBuilder} (the talk's Algorithm 1, written once
 * for every builder; subclasses decide {@code terminate} and {@code findPlane}) over one node
 * store, viewed as {@link org.kdtree.build.BuildNode}; its partition step; the median-plane,
 * object-median, sliding-midpoint and SAH builders with the SAH's plane searches; and
 * {@link org.kdtree.build.Builders}, which finds every builder on the class path through
 * {@link java.util.ServiceLoader}. {@link org.kdtree.build.Supervisor} runs an untrusted (a
 * student's) builder on a thread of its own within deadlines, and names its faults
 * ({@link org.kdtree.build.BuilderFault}).
 *
 * <p>Layer 5: it may use {@code limits}, {@code geom}, {@code shape}, {@code tree}, {@code traverse} and {@code bvh} (whose builder the one specification names); never a
 * package above it, so a builder of a student's jar joins without a change here.
 */
package org.kdtree.build;
