package org.kdtree.treefile;

import org.kdtree.accel.AccelerationStructure;
import org.kdtree.accel.TreeStats;
import org.kdtree.spec.BuilderSpec;

/**
 * A tree read from a file: the structure, ready for queries over the primitives it was loaded
 * over, and what the file says of its build.
 *
 * @param structure the kd-tree or bounding volume hierarchy
 * @param spec      the builder and the settings it was given, as the one builder specification holds them
 * @param settings  every setting the builder built with, in one line (its {@code describeSettings} at save time)
 * @param stats     the statistics the file states, which are the structure's own (checked on loading)
 */
public record SavedTree(AccelerationStructure structure, BuilderSpec spec, String settings, TreeStats stats) {
}
