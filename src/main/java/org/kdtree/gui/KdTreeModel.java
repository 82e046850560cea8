package org.kdtree.gui;

import java.util.ArrayList;
import java.util.BitSet;
import java.util.List;
import java.util.Locale;
import javax.swing.event.TreeModelListener;
import javax.swing.tree.TreePath;
import org.kdtree.kdtree.KdTree;

/** A Swing {@link TreeModel} read straight from a {@link KdTree}'s arrays: no copy, so big trees open at once. */
final class KdTreeModel implements TreeNodeView.Nodes {
    /** One node, shown as its split plane (and whether a lookahead kept it past a local minimum) or its leaf contents. */
    public record NodeRef(KdTree tree, BitSet pastMinimum, int node) {
        @Override public String toString() {
            if (!tree.isLeaf(node))
                return String.format(Locale.ROOT, "#%d  %s = %.3f%s", node, tree.axis(node) == 0 ? "x" : "y", tree.split(node),
                        pastMinimum.get(node) ? "  " + KdTreeView.PAST_MINIMUM : "");
            int n = tree.leafSize(node);
            if (n == 0) return "#" + node + "  empty leaf";
            StringBuilder b = new StringBuilder("#" + node + "  leaf: ");
            for (int i = 0; i < Math.min(n, 8); i++) b.append(i == 0 ? "" : ", ").append(tree.ref(tree.leafStart(node) + i));
            return b.append(n > 8 ? ", ... (" + n + ")" : "").toString();
        }
    }

    private final KdTree tree;
    private final BitSet pastMinimum;

    /**
     * A Swing tree model over the nodes of {@code tree}.
     *
     * @param tree the kd-tree
     * @param pastMinimum the interior nodes whose splits a lookahead kept past a local minimum ({@link KdTreeView#pastMinimum})
     */
    public KdTreeModel(KdTree tree, BitSet pastMinimum) {
        this.tree = tree;
        this.pastMinimum = pastMinimum;
    }

    @Override public Object getRoot() { return new NodeRef(tree, pastMinimum, 0); }

    @Override public int node(Object value) { return ((NodeRef) value).node(); }

    @Override public Object getChild(Object parent, int index) {
        int n = ((NodeRef) parent).node();
        return new NodeRef(tree, pastMinimum, index == 0 ? tree.leftChild(n) : tree.rightChild(n));
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
        path.add(new NodeRef(tree, pastMinimum, 0));
        while (n != node && !tree.isLeaf(n)) {
            n = node < tree.rightChild(n) ? tree.leftChild(n) : tree.rightChild(n);
            path.add(new NodeRef(tree, pastMinimum, n));
        }
        return new TreePath(path.toArray());
    }

    @Override public void valueForPathChanged(TreePath path, Object newValue) { }
    @Override public void addTreeModelListener(TreeModelListener l) { }
    @Override public void removeTreeModelListener(TreeModelListener l) { }
}
