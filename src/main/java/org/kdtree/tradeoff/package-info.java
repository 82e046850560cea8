/**
 * The measured trade-offs: every builder variant on one scene and ray workload (build time,
 * expected cost, trace speed, Pareto front), the nearest-neighbour study, and their charts.
 *
 * <p>Layer 7: it may use the packages of layers 1 to 6.
 */
package org.kdtree.tradeoff;
