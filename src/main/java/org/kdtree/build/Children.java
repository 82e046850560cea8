package org.kdtree.build;

/** The two children of a split: the left (lower) and the right (upper) voxel with their primitives. */
public record Children(BuildNode left, BuildNode right) {
}
