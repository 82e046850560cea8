package org.kdtree.gui;

import javax.swing.JScrollPane;
import javax.swing.JTree;
import javax.swing.tree.TreePath;
import javax.swing.tree.TreeSelectionModel;

/** The tree as a {@link JTree}, kept in step with the canvas: hovering a leaf selects it here, and picking a node here highlights its voxel. */
final class TreeNodeView extends JScrollPane {
    /** The Swing tree showing the kd-tree's nodes. */
    private final JTree jtree = new JTree();
    /** The model whose tree is shown and whose selected node follows this view's. */
    private final WorkbenchModel model;
    /** The Swing model over the current kd-tree. */
    private KdTreeModel treeModel;
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
        jtree.setToolTipText("The kd-tree: interior nodes show their split plane, leaves their objects; select one to highlight its voxel");
        jtree.getSelectionModel().setSelectionMode(TreeSelectionModel.SINGLE_TREE_SELECTION);
        jtree.addTreeSelectionListener(e -> {
            if (syncing || e.getNewLeadSelectionPath() == null) return;
            syncing = true;
            try {
                model.selectNode(((KdTreeModel.NodeRef) e.getNewLeadSelectionPath().getLastPathComponent()).node());
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
            treeModel = new KdTreeModel(model.tree());
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
