package org.kdtree.gui;

import javax.swing.JScrollPane;
import javax.swing.JTree;
import javax.swing.tree.TreeModel;
import javax.swing.tree.TreePath;
import javax.swing.tree.TreeSelectionModel;

/**
 * The tree (or bounding volume hierarchy) as a {@link JTree}, kept in step with the canvas:
 * hovering a leaf selects it here, and picking a node here highlights its voxel or box.
 */
final class TreeNodeView extends JScrollPane {
    /** A Swing tree model over a structure's nodes, which knows each node's index and path. */
    interface Nodes extends TreeModel {
        /**
         * {@return the index of the node a value of this model stands for}
         *
         * @param value a node of this model
         */
        int node(Object value);

        /**
         * {@return the path from the root to {@code node}}
         *
         * @param node a node's index
         */
        TreePath pathTo(int node);
    }

    /** The Swing tree showing the kd-tree's nodes. */
    private final JTree jtree = new JTree();
    /** The model whose tree is shown and whose selected node follows this view's. */
    private final WorkbenchModel model;
    /** The Swing model over the current kd-tree or hierarchy. */
    private Nodes treeModel;
    /** True while the view follows the model's selection, so that it does not select back. */
    private boolean syncing;

    /**
     * A view of the nodes of the tree of {@code model}.
     *
     * @param model the workbench's model
     */
    public TreeNodeView(WorkbenchModel model) {
        this.model = model;
        jtree.setName("kdtree");
        jtree.setToolTipText("The kd-tree (interior nodes show their split plane) or hierarchy (their box); leaves show their objects; select one to highlight it");
        jtree.getSelectionModel().setSelectionMode(TreeSelectionModel.SINGLE_TREE_SELECTION);
        jtree.addTreeSelectionListener(e -> {
            if (syncing || e.getNewLeadSelectionPath() == null) return;
            syncing = true;
            try {
                model.selectNode(treeModel.node(e.getNewLeadSelectionPath().getLastPathComponent()));
            } finally {
                syncing = false;
            }
        });
        setViewportView(jtree);
        model.addListener(c -> {
            if (c == WorkbenchModel.Change.TREE) reload();
            if (c != WorkbenchModel.Change.RAY && c != WorkbenchModel.Change.QUERY) follow();
        });
        reload();
    }

    /** {@return the Swing tree} */
    public JTree jtree() { return jtree; }

    private void reload() {
        syncing = true;
        try {
            Built b = model.built();
            treeModel = b.treeNodes();
            jtree.setModel(treeModel);
        } finally {
            syncing = false;
        }
    }

    private void follow() {
        if (syncing) return;
        syncing = true;
        try {
            int n = model.selectedNode();
            if (n < 0) {
                jtree.clearSelection();
            } else {
                TreePath p = treeModel.pathTo(n);
                jtree.setSelectionPath(p);
                jtree.scrollPathToVisible(p);
            }
        } finally {
            syncing = false;
        }
    }
}
