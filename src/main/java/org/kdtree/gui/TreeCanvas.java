package org.kdtree.gui;

import java.awt.BasicStroke;
import java.awt.Dimension;
import java.awt.Graphics2D;
import java.awt.Graphics;
import java.awt.event.MouseAdapter;
import java.awt.event.MouseEvent;
import java.awt.event.MouseWheelEvent;
import java.awt.geom.Line2D;
import java.awt.image.BufferedImage;
import java.util.ArrayList;
import java.util.List;
import javax.swing.JComponent;
import javax.swing.SwingUtilities;
import org.kdtree.shape.Shape2D;

/**
 * The 2-D build canvas: the scene and its tree (see {@link TreePainter}) or bounding volume
 * hierarchy (see {@link BvhPainter}), the leaf under the
 * mouse highlighted, zoom with the wheel, pan with the right or middle button, and left-button
 * editing, ray casting or placing the k-NN query according to the current {@link EditTool}.
 */
final class TreeCanvas extends JComponent {
    /** The model whose scene and tree are drawn and edited. */
    private final WorkbenchModel model;
    /** Maps scene coordinates to pixels. */
    private final ViewTransform view = new ViewTransform();
    /** Painted over the scene and tree (the steppers). */
    private final List<CanvasOverlay> overlays = new ArrayList<>();
    /** The edit tool in use. */
    private EditTool tool = EditTool.SELECT;
    /** True once the view was fitted to the scene; false while the canvas had no size to fit into. */
    private boolean fitted;
    /** The shape or new shape being dragged, drawn as a preview until the drag ends. */
    private Shape2D preview;

    /**
     * A canvas drawing and editing the scene and tree of {@code model}.
     *
     * @param model the workbench's model
     */
    public TreeCanvas(WorkbenchModel model) {
        this.model = model;
        setPreferredSize(new Dimension(720, 640));
        setFocusable(true);
        setToolTipText("Scene and kd-tree (or bounding volume hierarchy): wheel zooms, right-drag pans, F fits; the leaf under the mouse is highlighted; "
                + "dashed pink split lines: " + KdTreeView.PAST_MINIMUM + ", their own split does not beat the leaf, the subtree below does");
        model.addListener(c -> repaint());
        Mouse m = new Mouse();
        addMouseListener(m);
        addMouseMotionListener(m);
        addMouseWheelListener(m);
    }

    /** {@return the edit tool in use} */
    public EditTool tool() { return tool; }

    /**
     * Switches to another edit tool.
     *
     * @param t the tool
     */
    public void setTool(EditTool t) {
        tool = t;
        setCursor(java.awt.Cursor.getPredefinedCursor(t == EditTool.SELECT ? java.awt.Cursor.DEFAULT_CURSOR
                : java.awt.Cursor.CROSSHAIR_CURSOR));
    }

    /** {@return the view, mapping scene coordinates to pixels} */
    public ViewTransform view() { return view; }

    /**
     * Adds something to paint over the scene and tree.
     *
     * @param o the overlay
     */
    public void addOverlay(CanvasOverlay o) { overlays.add(o); }

    /** Fits the whole scene into the canvas. */
    public void fit() {
        if (getWidth() > 0) {
            view.fit(model.built().bounds(), getWidth(), getHeight());
            fitted = true;
        } else {
            fitted = false;
        }
        repaint();
    }

    /**
     * Zooms by {@code factor} around the canvas's centre.
     *
     * @param factor above 1 to zoom in, below 1 to zoom out
     */
    public void zoom(double factor) {
        view.zoomAt(getWidth() / 2.0, getHeight() / 2.0, factor);
        repaint();
    }

    @Override protected void paintComponent(Graphics g0) {
        if (!fitted && getWidth() > 0) fit();
        Graphics2D g = (Graphics2D) g0.create();
        try {
            paintScene(g, view, getWidth(), getHeight());
        } finally {
            g.dispose();
        }
    }

    /** A banner over the top: the tree shown is the previous one, since the builder failed. */
    private void paintStale(Graphics2D g, int w) {
        String text = "stale: the previous tree; builder " + model.fault().builder() + " failed (see the builder panel)";
        g.setColor(new java.awt.Color(170, 0, 0, 200));
        g.fillRect(0, 0, w, g.getFontMetrics().getHeight() + 8);
        g.setColor(java.awt.Color.WHITE);
        g.drawString(text, 6, g.getFontMetrics().getAscent() + 4);
    }

    /** The scene and tree without selection, kept while tree, view and size stay the same. */
    private BufferedImage base;
    /** The build {@link #base} shows. */
    private Built baseTree;
    /** The view {@link #base} was painted with. */
    private ViewTransform baseView;

    private void paintScene(Graphics2D g, ViewTransform v, int w, int h) {
        if (base == null || base.getWidth() != w || base.getHeight() != h || baseTree != model.built() || !v.sameAs(baseView)) {
            base = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
            Graphics2D bg = base.createGraphics();
            model.built().paint(bg, w, h, model.scene(), v, TreePainter.Options.PLAIN);
            bg.dispose();
            baseTree = model.built();
            baseView = v.copy();
        }
        g.drawImage(base, 0, 0, null);
        model.built().paintSelection(g, model.scene(), v, model.selectedNode(), model.selectedShape());
        for (CanvasOverlay o : overlays) o.paint(g, v);
        if (model.stale()) paintStale(g, w);
        if (preview != null)
            TreePainter.paintShape(g, preview, v, Palette.SELECTED_SHAPE, null,
                    new BasicStroke(2f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10, new float[] {4, 3}, 0));
    }

    /** {@return the canvas as it looks now, at its current size} (for PNG export). */
    public BufferedImage snapshot() {
        int w = Math.max(getWidth(), 1), h = Math.max(getHeight(), 1);
        if (!fitted) fit();
        BufferedImage img = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = img.createGraphics();
        paintScene(g, view, w, h);
        g.dispose();
        return img;
    }

    /** Handles hover, editing, ray casting, zoom and pan. */
    private final class Mouse extends MouseAdapter {
        private int lastX, lastY;
        private double startX, startY;
        private boolean panning;
        private int dragShape = -1, dragHandle = -1;

        private double tol() { return 5 / view.scale(); }

        @Override public void mouseMoved(MouseEvent e) {
            if (model.ray() != null || model.query() != null) return;   // then the selected node is a stepper's
            model.selectNode(model.built().leafAt(view.worldX(e.getX()), view.worldY(e.getY())));
        }

        @Override public void mousePressed(MouseEvent e) {
            requestFocusInWindow();
            lastX = e.getX();
            lastY = e.getY();
            startX = view.worldX(e.getX());
            startY = view.worldY(e.getY());
            panning = !SwingUtilities.isLeftMouseButton(e);
            if (!panning && tool == EditTool.KNN) model.setQuery(startX, startY);
            if (panning || tool != EditTool.SELECT) return;
            List<Shape2D> shapes = model.scene().shapes();
            int sel = model.selectedShape();
            dragHandle = sel >= 0 ? ShapeEditing.vertexNear(shapes.get(sel), startX, startY, tol()) : -1;
            dragShape = dragHandle >= 0 ? sel : ShapeEditing.pick(shapes, startX, startY, tol());
            model.selectShape(dragShape);
        }

        @Override public void mouseDragged(MouseEvent e) {
            double x = view.worldX(e.getX()), y = view.worldY(e.getY());
            if (panning) {
                view.pan(e.getX() - lastX, e.getY() - lastY);
            } else if (tool == EditTool.RAY) {
                model.setRay(startX, startY, x, y);
            } else if (tool == EditTool.KNN) {
                model.setQuery(x, y);
            } else if (tool == EditTool.SELECT) {
                if (dragShape >= 0) preview = edited(x, y);
            } else {
                preview = ShapeEditing.created(tool, startX, startY, x, y);
            }
            lastX = e.getX();
            lastY = e.getY();
            repaint();
        }

        @Override public void mouseReleased(MouseEvent e) {
            double x = view.worldX(e.getX()), y = view.worldY(e.getY());
            preview = null;
            if (panning) {
                panning = false;
            } else if (tool == EditTool.RAY) {
                if (x != startX || y != startY) model.setRay(startX, startY, x, y);
            } else if (tool == EditTool.KNN) {
                if (x != startX || y != startY) model.setQuery(x, y);
            } else if (tool == EditTool.SELECT) {
                if (dragShape >= 0 && (x != startX || y != startY)) model.replaceShape(dragShape, edited(x, y));
            } else {
                Shape2D s = ShapeEditing.created(tool, startX, startY, x, y);
                if (s != null && (tool == EditTool.POINT || x != startX || y != startY)) model.addShape(s);
            }
            dragShape = dragHandle = -1;
            repaint();
        }

        private Shape2D edited(double x, double y) {
            Shape2D s = model.scene().get(dragShape);
            return dragHandle >= 0 ? ShapeEditing.moveHandle(s, dragHandle, x, y)
                    : ShapeEditing.translate(s, x - startX, y - startY);
        }

        @Override public void mouseWheelMoved(MouseWheelEvent e) {
            view.zoomAt(e.getX(), e.getY(), Math.pow(1.15, -e.getPreciseWheelRotation()));
            repaint();
        }
    }

    /** Draws a segment between two scene points, for overlays. */
    static Line2D.Double line(ViewTransform v, double x0, double y0, double x1, double y1) {
        return new Line2D.Double(v.screenX(x0), v.screenY(y0), v.screenX(x1), v.screenY(y1));
    }
}
