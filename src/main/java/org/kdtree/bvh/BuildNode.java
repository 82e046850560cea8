package org.kdtree.bvh;

/**
 * A node of a hierarchy being built: its box, and its two children or its stretch of the
 * primitive order. Lives only during a build; {@link Bvh#of} lays the tree out in flat arrays.
 */
final class BuildNode {
    /** k minima, then k maxima. */
    final double[] box;
    BuildNode left, right;
    /** Its centroids' bounds (doubled: min + max), k minima then k maxima, while it waits to be split. */
    double[] centroids;
    int first, count;
    private int nodes = 1;

    BuildNode(int k) {
        box = new double[2 * k];
    }

    BuildNode leaf(int first, int count) {
        this.first = first;
        this.count = count;
        return this;
    }

    BuildNode interior(BuildNode left, BuildNode right) {
        this.left = left;
        this.right = right;
        this.nodes = 1 + left.nodes + right.nodes;
        return this;
    }

    boolean isLeaf() { return left == null; }

    /** {@return the nodes of the subtree} */
    int size() { return nodes; }
}
