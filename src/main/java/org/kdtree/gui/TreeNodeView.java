package org.kdtree.gui;

import javax.swing.JScrollPane;
import javax.swing.JTree;
import javax.swing.tree.TreePath;
import javax.swing.tree.TreeSelectionModel;

/** The tree as a {@link JTree}, kept in step with the canvas: hovering a leaf selects it here, and picking a node here highlights its voxel. */
public final class TreeNodeView extends JScrollPane {
    private final JTree jtree = new JTree();
    private final WorkbenchModel model;
    private KdTreeModel treeModel;
    private boolean syncing;

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
