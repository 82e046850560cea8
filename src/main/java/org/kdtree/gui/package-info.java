/**
 * The Swing workbench: the 2-D build canvas, the traversal and nearest-neighbour steppers
 * (replaying listener events), the builder comparison, collisions, and the 3-D view (rendering
 * with {@code render}). Only {@link org.kdtree.gui.Workbench} and what the benchmarks measure
 * are public.
 *
 * <p>Layer 9: it may use every package but {@code cli}.
 */
package org.kdtree.gui;
