/**
 * Ray tracing a {@code scene}: the effect plan (which rays a scene needs, decided before the
 * first ray), the Whitted tracer (allocation-free per ray), the tiled multi-threaded renderer
 * with progress and stop, and PNG output.
 *
 * <p>Layer 7: it may use the packages of layers 1 to 6; not {@code io}, which is the caller's
 * business.
 */
package org.kdtree.render;
