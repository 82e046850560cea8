package org.kdtree.contract;

import java.util.ArrayList;
import java.util.List;
import org.kdtree.geom.Box;
import org.kdtree.tree.KdTree;
import org.kdtree.tree.TreeVisitor;

/** The nodes of a tree as plain objects, for checking invariants in tests. */
public final class TreeInspector {
    /** A leaf: its node index, depth, voxel (a copy) and primitives. */
    public record Leaf(int node, int depth, Box voxel, int[] refs) {
    }

    /** An interior node: its voxel (a copy) and split plane. */
    public record Interior(int node, int depth, Box voxel, int axis, double split) {
    }

    private final KdTree tree;
    private final List<Leaf> leaves = new ArrayList<>();
    private final List<Interior> interiors = new ArrayList<>();
    private final java.util.Map<Integer, Leaf> leafByNode = new java.util.HashMap<>();

    public TreeInspector(KdTree tree) {
        this.tree = tree;
        tree.walk(new TreeVisitor() {
            @Override public void interior(int node, int depth, Box voxel, int axis, double split) {
                interiors.add(new Interior(node, depth, voxel.copy(), axis, split));
            }

            @Override public void leaf(int node, int depth, Box voxel, int[] refs, int from, int to) {
                Leaf l = new Leaf(node, depth, voxel.copy(), java.util.Arrays.copyOfRange(refs, from, to));
                leaves.add(l);
                leafByNode.put(node, l);
            }
        });
    }

    public List<Leaf> leaves() { return leaves; }
    public List<Interior> interiors() { return interiors; }

    /** The leaves whose closed voxel, grown by {@code eps}, contains point p. */
    public List<Leaf> leavesContaining(double[] p, double eps) {
        List<Leaf> out = new ArrayList<>();
        collect(0, tree.bounds(), p, eps, out);
        return out;
    }

    private void collect(int node, Box voxel, double[] p, double eps, List<Leaf> out) {
        if (tree.isLeaf(node)) {
            out.add(leafByNode.get(node));
            return;
        }
        int axis = tree.axis(node);
        double xi = tree.split(node);
        if (p[axis] <= xi + eps) collect(tree.leftChild(node), voxel.lowerPart(axis, xi), p, eps, out);
        if (p[axis] >= xi - eps) collect(tree.rightChild(node), voxel.upperPart(axis, xi), p, eps, out);
    }
}
