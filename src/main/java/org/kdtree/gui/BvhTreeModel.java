package org.kdtree.gui;

import java.util.ArrayDeque;
import java.util.Deque;
import java.util.Locale;
import javax.swing.event.TreeModelListener;
import javax.swing.tree.TreePath;
import org.kdtree.bvh.Bvh;

/**
 * A Swing tree model read straight from a {@link Bvh}'s binary layout, as {@link KdTreeModel}
 * reads a kd-tree: interior nodes show their box, leaves their objects.
 */
final class BvhTreeModel implements TreeNodeView.Nodes {
    /** One node, shown as its box or its leaf's objects. */
    record NodeRef(Bvh bvh, int node) {
        @Override public String toString() {
            String box = String.format(Locale.ROOT, "[%.2f, %.2f] x [%.2f, %.2f]", bvh.min(node, 0), bvh.max(node, 0),
                    bvh.min(node, 1), bvh.max(node, 1));
            if (!bvh.isLeaf(node)) return "#" + node + "  box " + box;
            int n = bvh.leafSize(node);
            StringBuilder b = new StringBuilder("#" + node + "  leaf: ");
            for (int i = 0; i < Math.min(n, 8); i++) b.append(i == 0 ? "" : ", ").append(bvh.primitive(bvh.leafStart(node) + i));
            return b.append(n > 8 ? ", ... (" + n + ")" : "").toString();
        }
    }

    private final Bvh bvh;
    /** Each node's parent (the root's is -1): the binary layout does not order nodes by a comparison, as a kd-tree's does. */
    private final int[] parent;

    /**
     * A Swing tree model over the nodes of {@code bvh}.
     *
     * @param bvh the hierarchy
     */
    BvhTreeModel(Bvh bvh) {
        this.bvh = bvh;
        parent = new int[bvh.nodeCount()];
        parent[0] = -1;
        for (int n = 0; n < parent.length; n++)
            if (!bvh.isLeaf(n)) parent[bvh.left(n)] = parent[bvh.right(n)] = n;
    }

    @Override public Object getRoot() { return new NodeRef(bvh, 0); }

    @Override public int node(Object value) { return ((NodeRef) value).node(); }

    @Override public Object getChild(Object parentNode, int index) {
        int n = node(parentNode);
        return new NodeRef(bvh, index == 0 ? bvh.left(n) : bvh.right(n));
    }

    @Override public int getChildCount(Object node) { return bvh.isLeaf(node(node)) ? 0 : 2; }

    @Override public boolean isLeaf(Object node) { return bvh.isLeaf(node(node)); }

    @Override public int getIndexOfChild(Object parentNode, Object child) {
        int p = node(parentNode), c = node(child);
        if (bvh.isLeaf(p)) return -1;
        return c == bvh.left(p) ? 0 : c == bvh.right(p) ? 1 : -1;
    }

    @Override public TreePath pathTo(int node) {
        Deque<Object> path = new ArrayDeque<>();
        for (int n = node; n >= 0; n = parent[n]) path.addFirst(new NodeRef(bvh, n));
        return new TreePath(path.toArray());
    }

    @Override public void valueForPathChanged(TreePath path, Object newValue) { }
    @Override public void addTreeModelListener(TreeModelListener l) { }
    @Override public void removeTreeModelListener(TreeModelListener l) { }
}
