package org.kdtree.gui;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import org.kdtree.shape.Shape2D;
import org.kdtree.shape.Shapes2D;
import org.kdtree.tree.KdTree;

/**
 * The state the 2-D views share: the scene being edited, the builder settings, the tree built
 * from them (rebuilt at once on every change), the selected node and shape, and the cast ray.
 * Listeners hear what changed. Used on the Swing event thread only.
 */
public final class WorkbenchModel {
    /** What changed, so that a view redoes only what it must. */
    public enum Change { TREE, SELECTION, RAY }

    /** Hears the model's changes. */
    public interface Listener {
        void changed(Change what);
    }

    private final List<Listener> listeners = new CopyOnWriteArrayList<>();
    private List<Shape2D> shapes = new ArrayList<>();
    private Shapes2D scene = new Shapes2D(List.of());
    private String sceneName = "";
    private BuilderSettings settings = BuilderSettings.DEFAULT;
    private KdTree tree;
    private double buildMillis;
    private int selectedNode = -1;
    private int selectedShape = -1;
    private double[] ray;

    public WorkbenchModel() {
        rebuild();
    }

    public void addListener(Listener l) { listeners.add(l); }

    // ---- scene ----

    public Shapes2D scene() { return scene; }
    public String sceneName() { return sceneName; }

    /** Replaces the whole scene (and forgets the selection). */
    public void setScene(String name, List<? extends Shape2D> newShapes) {
        sceneName = name;
        shapes = new ArrayList<>(newShapes);
        selectedShape = -1;
        selectedNode = -1;
        rebuild();
    }

    /** Opens a .scene2d file (errors name the file and line). */
    public void load(java.nio.file.Path file) throws java.io.IOException {
        setScene(file.getFileName().toString(), org.kdtree.io.Scene2DFormat.read(file).shapes());
    }

    /** Saves the scene as a .scene2d file. */
    public void save(java.nio.file.Path file) throws java.io.IOException {
        org.kdtree.io.Scene2DFormat.write(scene, file);
    }

    public void addShape(Shape2D s) {
        shapes.add(s);
        selectedShape = shapes.size() - 1;
        rebuild();
    }

    public void replaceShape(int i, Shape2D s) {
        shapes.set(i, s);
        rebuild();
    }

    public void removeShape(int i) {
        shapes.remove(i);
        selectedShape = -1;
        rebuild();
    }

    // ---- builder ----

    public BuilderSettings settings() { return settings; }

    public void setSettings(BuilderSettings s) {
        if (s.equals(settings)) return;
        settings = s;
        rebuild();
    }

    public KdTree tree() { return tree; }

    /** Wall-clock time of the last build, in milliseconds. */
    public double buildMillis() { return buildMillis; }

    private void rebuild() {
        scene = new Shapes2D(shapes);
        long t0 = System.nanoTime();
        tree = settings.create().build(scene);
        buildMillis = (System.nanoTime() - t0) / 1e6;
        if (selectedNode >= tree.nodeCount()) selectedNode = -1;
        if (selectedShape >= shapes.size()) selectedShape = -1;
        fire(Change.TREE);
    }

    // ---- selection ----

    /** The selected tree node (the leaf under the mouse, or the node picked in the tree view), or -1. */
    public int selectedNode() { return selectedNode; }

    public void selectNode(int node) {
        if (node == selectedNode) return;
        selectedNode = node;
        fire(Change.SELECTION);
    }

    /** The shape being edited, or -1. */
    public int selectedShape() { return selectedShape; }

    public void selectShape(int i) {
        if (i == selectedShape) return;
        selectedShape = i;
        fire(Change.SELECTION);
    }

    // ---- ray ----

    /** The cast ray as {ox, oy, dx, dy}, or null. */
    public double[] ray() { return ray == null ? null : ray.clone(); }

    /** Casts a ray from (ox, oy) towards (tx, ty); a zero-length drag clears it. */
    public void setRay(double ox, double oy, double tx, double ty) {
        double dx = tx - ox, dy = ty - oy;
        ray = dx == 0 && dy == 0 ? null : new double[] {ox, oy, dx, dy};
        fire(Change.RAY);
    }

    public void clearRay() {
        ray = null;
        fire(Change.RAY);
    }

    private void fire(Change c) {
        for (Listener l : listeners) l.changed(c);
    }
}
