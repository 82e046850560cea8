package org.kdtree.gui;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import javax.swing.event.TreeModelListener;
import javax.swing.tree.TreePath;
import org.kdtree.kdtree.KdTree;

/** A Swing {@link TreeModel} read straight from a {@link KdTree}'s arrays: no copy, so big trees open at once. */
final class KdTreeModel implements TreeNodeView.Nodes {
    /** One node, shown as its split plane or its leaf contents. */
    public record NodeRef(KdTree tree, int node) {
        @Override public String toString() {
            if (!tree.isLeaf(node))
                return String.format(Locale.ROOT, "#%d  %s = %.3f", node, tree.axis(node) == 0 ? "x" : "y", tree.split(node));
            int n = tree.leafSize(node);
            if (n == 0) return "#" + node + "  empty leaf";
            StringBuilder b = new StringBuilder("#" + node + "  leaf: ");
            for (int i = 0; i < Math.min(n, 8); i++) b.append(i == 0 ? "" : ", ").append(tree.ref(tree.leafStart(node) + i));
            return b.append(n > 8 ? ", ... (" + n + ")" : "").toString();
        }
    }

    private final KdTree tree;

    /**
     * A Swing tree model over the nodes of {@code tree}.
     *
     * @param tree the kd-tree
     */
    public KdTreeModel(KdTree tree) {
        this.tree = tree;
    }

    @Override public Object getRoot() { return new NodeRef(tree, 0); }

    @Override public int node(Object value) { return ((NodeRef) value).node(); }

    @Override public Object getChild(Object parent, int index) {
        int n = ((NodeRef) parent).node();
        return new NodeRef(tree, index == 0 ? tree.leftChild(n) : tree.rightChild(n));
    }

    @Override public int getChildCount(Object parent) { return tree.isLeaf(((NodeRef) parent).node()) ? 0 : 2; }

    @Override public boolean isLeaf(Object node) { return tree.isLeaf(((NodeRef) node).node()); }

    @Override public int getIndexOfChild(Object parent, Object child) {
        int p = ((NodeRef) parent).node(), c = ((NodeRef) child).node();
        if (tree.isLeaf(p)) return -1;
        return c == tree.leftChild(p) ? 0 : c == tree.rightChild(p) ? 1 : -1;
    }

    /** {@return the path from the root to {@code node}}: nodes are stored depth first, so each step is one comparison. */
    @Override public TreePath pathTo(int node) {
        List<Object> path = new ArrayList<>();
        int n = 0;
        path.add(new NodeRef(tree, 0));
        while (n != node && !tree.isLeaf(n)) {
            n = node < tree.rightChild(n) ? tree.leftChild(n) : tree.rightChild(n);
            path.add(new NodeRef(tree, n));
        }
        return new TreePath(path.toArray());
    }

    @Override public void valueForPathChanged(TreePath path, Object newValue) { }
    @Override public void addTreeModelListener(TreeModelListener l) { }
    @Override public void removeTreeModelListener(TreeModelListener l) { }
}
