package org.kdtree.gui;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.CopyOnWriteArrayList;
import org.kdtree.kdtree.BuilderFault;
import org.kdtree.kdtree.KdTree;
import org.kdtree.shape.Scene2D;
import org.kdtree.shape.Shape2D;
import org.kdtree.spec.BuilderSpec;

/**
 * The state the 2-D views share: the scene being edited, the builder settings, the tree built
 * from them (rebuilt on every change), the selected node and shape, and the cast ray. The
 * builder may be the bounding volume hierarchy's ({@code bvh}): then {@link #built()} is the
 * hierarchy and {@link #tree()} is null, and the views that need a kd-tree say so. Listeners
 * hear what changed. Used on the Swing event thread only. It also holds the query point of the
 * nearest-neighbour stepper.
 *
 * <p>No build runs on the event thread: every build runs on the model's build thread, a
 * plug-in's under a supervisor with the workbench's deadlines ({@link BackgroundBuild}). For a scene of up
 * to {@link #BACKGROUND_ABOVE} objects the event thread waits for it a moment at the most (2 s
 * for the library's builders, which need milliseconds, a quarter of a second for a plug-in's), so
 * that a small scene's tree still appears within the event that changed it; past that (a large
 * scene, a slow or hung builder), listeners hear {@link Change#BUILDING}, the
 * views keep showing the last scene and tree until the new tree is ready, and a change made
 * meanwhile cancels the stale build (its thread is interrupted; a hung plug-in's is stopped).
 * A builder that throws, answers wrongly, hangs or is too slow leaves the last tree shown,
 * marked {@link #stale()}, and its {@link #fault()} said ({@link Change#FAULT}).
 */
final class WorkbenchModel {
    /** What changed, so that a view redoes only what it must. */
    public enum Change {
        /** A new scene or tree. */
        TREE,
        /** The selected node or shape. */
        SELECTION,
        /** The cast ray. */
        RAY,
        /** A background build started. */
        BUILDING,
        /** The k-NN query point. */
        QUERY,
        /** A build failed by the builder's fault: the tree shown is stale. */
        FAULT
    }

    /** Scenes with more objects than this are built in the background. */
    public static final int BACKGROUND_ABOVE = 20_000;


    /** Hears the model's changes. */
    public interface Listener {
        /**
         * Called after each change.
         *
         * @param what what changed
         */
        void changed(Change what);
    }

    private final List<Listener> listeners = new CopyOnWriteArrayList<>();
    private List<Shape2D> shapes = new ArrayList<>();
    private Scene2D scene = new Scene2D(List.of());
    private String sceneName = "";
    private BuilderSpec settings = BuilderSpec.of("sah");
    private Built built;
    /** What {@link #built} was built with (the settings may have moved on while a build runs). */
    private BuilderSpec builtWith = settings;
    /** The tree file {@link #built} was loaded from, or null if it was built here. */
    private java.nio.file.Path loadedFrom;
    private double buildMillis;
    private boolean building;
    private final BackgroundBuild builds = new BackgroundBuild("workbench build");
    private BuilderFault fault;
    private final Set<String> hung = new HashSet<>();
    private int selectedNode = -1;
    private int selectedShape = -1;
    private double[] ray;
    private double[] query;

    /** A model with an empty scene and the default builder settings. */
    public WorkbenchModel() {
        rebuild();
    }

    /**
     * Adds a listener of changes.
     *
     * @param l the listener
     */
    public void addListener(Listener l) { listeners.add(l); }

    // ---- scene ----

    /** {@return the scene} */
    public Scene2D scene() { return scene; }
    /** {@return the scene's name} */
    public String sceneName() { return sceneName; }

    /**
     * Replaces the whole scene (and forgets the selection).
     *
     * @param name the scene's name
     * @param newShapes the shapes
     */
    public void setScene(String name, List<? extends Shape2D> newShapes) {
        sceneName = name;
        shapes = new ArrayList<>(newShapes);
        selectedShape = -1;
        selectedNode = -1;
        rebuild();
    }

    /**
     * Opens a .scene2d file (errors name the file and line).
     *
     * @param file the file
     * @throws java.io.IOException if the file cannot be read or is malformed
     */
    public void load(java.nio.file.Path file) throws java.io.IOException {
        setScene(file.getFileName().toString(), org.kdtree.io.PrimitivesReader.readScene2D(file).shapes());
    }

    /**
     * Saves the scene as a .scene2d file.
     *
     * @param file the file, replaced if it exists
     * @throws java.io.IOException if writing fails
     */
    public void save(java.nio.file.Path file) throws java.io.IOException {
        org.kdtree.io.Scene2DWriter.write(scene, file);
    }

    /**
     * Adds a shape, selects it and rebuilds the tree.
     *
     * @param s the shape
     */
    public void addShape(Shape2D s) {
        shapes.add(s);
        selectedShape = shapes.size() - 1;
        rebuild();
    }

    /**
     * Replaces shape {@code i} and rebuilds the tree.
     *
     * @param i the shape's index
     * @param s the new shape
     */
    public void replaceShape(int i, Shape2D s) {
        shapes.set(i, s);
        rebuild();
    }

    /**
     * Removes shape {@code i}, clears the shape selection and rebuilds the tree.
     *
     * @param i the shape's index
     */
    public void removeShape(int i) {
        shapes.remove(i);
        selectedShape = -1;
        rebuild();
    }

    // ---- builder ----

    /** {@return the builder settings} */
    public BuilderSpec settings() { return settings; }

    /**
     * Changes the builder settings and rebuilds the tree (nothing happens if they are equal).
     *
     * @param s the new settings
     */
    public void setSettings(BuilderSpec s) {
        if (s.equals(settings)) return;
        settings = s;
        rebuild();
    }

    /**
     * {@return the kd-tree of the scene} (the previous one while a background build runs), or
     * null while the builder is the bounding volume hierarchy's
     */
    public KdTree tree() { return built.kdTree(); }

    /** {@return what the last build made, a kd-tree or a hierarchy} (the previous one while a background build runs) */
    public Built built() { return built; }

    /** {@return the wall-clock time of the last build (or load: {@link #loadedFrom()}), in milliseconds} */
    public double buildMillis() { return buildMillis; }

    /** {@return the tree file the tree shown was loaded from, or null if it was built here} */
    public java.nio.file.Path loadedFrom() { return loadedFrom; }

    /**
     * Saves the tree shown, with the settings it was built with, for {@link #loadTree} (File &gt; Save tree).
     *
     * @param file the tree file, replaced whole if it exists
     * @throws java.io.IOException if writing fails
     * @throws IllegalStateException while the tree shown is not the scene's (a build under way, or failed)
     */
    public void saveTree(java.nio.file.Path file) throws java.io.IOException {
        requireCurrent("save");
        org.kdtree.treefile.TreeFile.save(file, built.structure(), builtWith, scene);
    }

    /**
     * Shows the tree saved in {@code file} instead of building one: it must have been built over
     * this scene; its builder and settings become the workbench's (File &gt; Open tree).
     *
     * @param file a tree file
     * @throws java.io.IOException in one line if the file is not a tree of this scene, or cannot be read
     * @throws IllegalStateException while a build is under way or the tree shown is stale
     */
    public void loadTree(java.nio.file.Path file) throws java.io.IOException {
        requireCurrent("replace");
        long t0 = System.nanoTime();
        org.kdtree.treefile.SavedTree saved = org.kdtree.treefile.TreeFile.load(file, scene);
        double ms = (System.nanoTime() - t0) / 1e6;
        settings = saved.spec();
        install(scene, saved.spec(), Built.of(saved.structure(), saved.spec()), ms);
        loadedFrom = file;
        fire(Change.TREE);
    }

    private void requireCurrent(String what) {
        if (building || stale())
            throw new IllegalStateException("the tree shown is not the scene's yet (" + (building ? "a build is under way" : "its build failed")
                    + "): cannot " + what + " it");
    }

    /** {@return whether a background build is under way} (the views still show the previous tree). */
    public boolean building() { return building; }

    /** {@return the fault of the last build, or null if it built the tree shown} */
    public BuilderFault fault() { return fault; }

    /** {@return whether the tree shown is not that of the scene and settings: its build failed by the builder's fault} */
    public boolean stale() { return fault != null; }

    /**
     * {@return whether builder {@code name} hung (or was too slow) in this workbench}: it is
     * marked in the builder box until a build with it succeeds
     *
     * @param name a builder's name
     */
    public boolean hung(String name) { return hung.contains(name); }

    private void rebuild() {
        Scene2D next = new Scene2D(shapes);
        BuilderSpec spec = settings;
        if (builds.start(spec, next, next.size() <= BACKGROUND_ABOVE, o -> finish(next, spec, o))) return;
        building = true;
        fire(Change.BUILDING);
    }

    /** Shows the newest build's outcome: its tree, or its builder's fault over the last tree, then stale. */
    private void finish(Scene2D builtScene, BuilderSpec spec, BackgroundBuild.Outcome o) {
        building = false;
        if (o.fault() == null) {
            fault = null;
            hung.remove(o.built().builderName());
            install(builtScene, spec, o.built(), o.millis());
            fire(Change.TREE);
            return;
        }
        fault = o.fault();
        if (fault.kind() == BuilderFault.Kind.HUNG || fault.kind() == BuilderFault.Kind.SLOW) hung.add(fault.builder());
        fire(Change.FAULT);
    }

    /** Publishes a scene and its tree together, so that the views never pair a tree with another scene. */
    private void install(Scene2D builtScene, BuilderSpec spec, Built b, double ms) {
        scene = builtScene;
        built = b;
        builtWith = spec;
        loadedFrom = null;
        buildMillis = ms;
        if (selectedNode >= built.nodeCount()) selectedNode = -1;
        if (selectedShape >= shapes.size()) selectedShape = -1;
    }

    // ---- selection ----

    /** {@return the selected tree node (the leaf under the mouse, or the node picked in the tree view), or -1} */
    public int selectedNode() { return selectedNode; }

    /**
     * Selects a tree node.
     *
     * @param node the node's index, or -1 for none
     */
    public void selectNode(int node) {
        if (node == selectedNode) return;
        selectedNode = node;
        fire(Change.SELECTION);
    }

    /** {@return the shape being edited, or -1} */
    public int selectedShape() { return selectedShape; }

    /**
     * Selects a shape to edit.
     *
     * @param i the shape's index, or -1 for none
     */
    public void selectShape(int i) {
        if (i == selectedShape) return;
        selectedShape = i;
        fire(Change.SELECTION);
    }

    // ---- ray ----

    /** {@return the cast ray as {ox, oy, dx, dy}, or null} */
    public double[] ray() { return ray == null ? null : ray.clone(); }

    /**
     * Casts a ray from (ox, oy) towards (tx, ty); a zero-length drag clears it.
     *
     * @param ox the origin's x
     * @param oy the origin's y
     * @param tx x of a point the ray passes through
     * @param ty y of that point
     */
    public void setRay(double ox, double oy, double tx, double ty) {
        double dx = tx - ox, dy = ty - oy;
        ray = dx == 0 && dy == 0 ? null : new double[] {ox, oy, dx, dy};
        fire(Change.RAY);
    }

    /** Removes the cast ray. */
    public void clearRay() {
        ray = null;
        fire(Change.RAY);
    }

    // ---- nearest-neighbour query ----

    /** {@return the query point of the k-NN stepper as {x, y}, or null} */
    public double[] query() { return query == null ? null : query.clone(); }

    /**
     * Places the k-NN query point at (x, y).
     *
     * @param x the query point's x
     * @param y the query point's y
     */
    public void setQuery(double x, double y) {
        query = new double[] {x, y};
        fire(Change.QUERY);
    }

    /** Removes the k-NN query point. */
    public void clearQuery() {
        query = null;
        fire(Change.QUERY);
    }

    private void fire(Change c) {
        for (Listener l : listeners) l.changed(c);
    }
}
