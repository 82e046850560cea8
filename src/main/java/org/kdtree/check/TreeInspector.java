package org.kdtree.check;

import java.util.ArrayList;
import java.util.List;
import org.kdtree.geom.Box;
import org.kdtree.kdtree.KdTree;
import org.kdtree.kdtree.TreeVisitor;

/** The nodes of a tree as plain objects, for checking its invariants (the contract, the grading). */
final class TreeInspector {
    /**
     * A leaf.
     * @param node its node index
     * @param depth its depth (the root's is 0)
     * @param voxel its voxel (a copy)
     * @param refs the primitives it lists
     */
    public record Leaf(int node, int depth, Box voxel, int[] refs) {
    }

    /**
     * An interior node.
     * @param node its node index
     * @param depth its depth (the root's is 0)
     * @param voxel its voxel (a copy)
     * @param axis the split plane's axis
     * @param split the split plane's position
     */
    public record Interior(int node, int depth, Box voxel, int axis, double split) {
    }

    private final KdTree tree;
    private final List<Leaf> leaves = new ArrayList<>();
    private final List<Interior> interiors = new ArrayList<>();
    private final java.util.Map<Integer, Leaf> leafByNode = new java.util.HashMap<>();

    /**
     * Walks the tree once.
     * @param tree the tree to inspect
     */
    public TreeInspector(KdTree tree) {
        this.tree = tree;
        tree.walk(new TreeVisitor() {
            @Override public void interior(int node, int depth, Box voxel, int axis, double split) {
                interiors.add(new Interior(node, depth, voxel.copy(), axis, split));
            }

            @Override public void leaf(int node, int depth, Box voxel, int from, int to) {
                Leaf l = new Leaf(node, depth, voxel.copy(), tree.leafPrimitives(node));
                leaves.add(l);
                leafByNode.put(node, l);
            }
        });
    }

    /** {@return the leaves, depth first} */
    public List<Leaf> leaves() { return leaves; }

    /** {@return the interior nodes, depth first} */
    public List<Interior> interiors() { return interiors; }

    /**
     * The leaves whose closed voxel, grown by {@code eps}, contains point p.
     * @param p the point
     * @param eps the margin
     * @return those leaves
     */
    public List<Leaf> leavesContaining(double[] p, double eps) {
        List<Leaf> out = new ArrayList<>();
        collect(0, p, eps, out);
        return out;
    }

    private void collect(int node, double[] p, double eps, List<Leaf> out) {
        if (tree.isLeaf(node)) {
            out.add(leafByNode.get(node));
            return;
        }
        int axis = tree.axis(node);
        double xi = tree.split(node);
        if (p[axis] <= xi + eps) collect(tree.leftChild(node), p, eps, out);
        if (p[axis] >= xi - eps) collect(tree.rightChild(node), p, eps, out);
    }
}
