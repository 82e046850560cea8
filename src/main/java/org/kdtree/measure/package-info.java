/**
 * What the measuring applications share: the benchmark spec's ray sets ({@link org.kdtree.measure.RaySet},
 * drawn from {@code SplitMix64}), the one ray-batch tracer ({@link org.kdtree.measure.RayBatch}) and
 * the median of timed runs ({@link org.kdtree.measure.Timing}), used by the command line's
 * {@code raycast} and {@code stats}, the trade-off study and the benchmarks. In the applications'
 * room: no package of the library uses it.
 *
 * <p>Layer 6: it may use the packages of layers 1 to 5.
 */
package org.kdtree.measure;
