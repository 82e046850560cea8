package org.kdtree.gui;

import java.util.ArrayList;
import java.util.List;
import org.kdtree.accel.AccelerationStructure;
import org.kdtree.accel.Hit;
import org.kdtree.accel.RayQuery;
import org.kdtree.accel.TraversalListener;
import org.kdtree.accel.TraversalStats;
import org.kdtree.geom.Ray;
import org.kdtree.kdtree.KdTree;
import org.kdtree.kdtree.Traverser;
import org.kdtree.shape.Scene2D;

/**
 * Records the real traversal (a kd-tree's {@link Traverser#closestHit}, or a bounding volume
 * hierarchy's, with a {@link TraversalListener}) into a {@link TraversalTrace}: the stepper
 * replays what the library did, it does not traverse on its own.
 */
final class TraversalRecorder implements TraversalListener {
    private final List<TraversalTrace.Step> steps = new ArrayList<>();
    private final List<TraversalTrace.Entry> stack = new ArrayList<>();
    private final List<Integer> tested = new ArrayList<>();
    private final List<TraversalTrace.BoxTest> boxes = new ArrayList<>();
    private int node = -1;
    private double tMin = Double.NaN, tMax = Double.NaN;
    private int best = -1;
    private double bestT = Double.NaN;

    private TraversalRecorder() {
    }

    /**
     * Traces the closest hit of the 2-D ray {ox, oy, dx, dy} (t >= 0) through {@code tree}.
     *
     * @param tree the kd-tree over {@code scene}
     * @param scene the 2-D scene
     * @param ray the ray {ox, oy, dx, dy}, or null
     * @return the recorded traversal ({@link TraversalTrace#EMPTY} without a ray)
     */
    public static TraversalTrace record(KdTree tree, Scene2D scene, double[] ray) {
        return record((AccelerationStructure) tree, scene, ray);
    }

    /**
     * Traces the closest hit of the 2-D ray {ox, oy, dx, dy} (t >= 0) through {@code structure},
     * a kd-tree or a bounding volume hierarchy, counting as {@link TraversalStats} does.
     *
     * @param structure the structure over {@code scene}
     * @param scene the 2-D scene
     * @param ray the ray {ox, oy, dx, dy}, or null
     * @return the recorded traversal ({@link TraversalTrace#EMPTY} without a ray)
     */
    public static TraversalTrace record(AccelerationStructure structure, Scene2D scene, double[] ray) {
        if (ray == null) return TraversalTrace.EMPTY;
        TraversalRecorder rec = new TraversalRecorder();
        TraversalStats stats = new TraversalStats();
        Hit hit = new Hit();
        RayQuery query = structure.query(new Both(rec, stats));
        boolean found = query.closestHit(new Ray(2).set(ray[0], ray[1], ray[2], ray[3]), 0, Double.POSITIVE_INFINITY, hit);
        return new TraversalTrace(List.copyOf(rec.steps), stats.nodes, stats.leaves, stats.primitiveTests, stats.boxTests,
                found ? hit.primitive : -1, found ? hit.t : Double.NaN);
    }

    private void add(TraversalTrace.Kind kind, double tSplit, int near, int far, String visit, int object, boolean hit) {
        steps.add(new TraversalTrace.Step(kind, node, tMin, tMax, tSplit, near, far, visit, List.copyOf(stack),
                List.copyOf(tested), List.copyOf(boxes), object, hit, best, bestT));
    }

    private void at(int n, double lo, double hi) {
        node = n;
        tMin = lo;
        tMax = hi;
    }

    @Override public void begin(double lo, double hi) {
        at(-1, lo, hi);
        add(TraversalTrace.Kind.BEGIN, Double.NaN, -1, -1, "", -1, false);
    }

    @Override public void missedScene() {
        add(TraversalTrace.Kind.MISSED_SCENE, Double.NaN, -1, -1, "", -1, false);
    }

    @Override public void interior(int n, int axis, double split, double lo, double hi, double tSplit,
                                   int near, int far, Visit visit) {
        at(n, lo, hi);
        tested.clear();
        add(TraversalTrace.Kind.INTERIOR, tSplit, near, far, switch (visit) {
            case NEAR -> "near only";
            case FAR -> "far only";
            case BOTH -> "near, then far";
            case BOTH_IN_PLANE -> "both (ray in the plane)";
        }, -1, false);
    }

    @Override public void boxNode(int n, double lo, double hi) {
        at(n, lo, hi);
        tested.clear();
        boxes.clear();
        add(TraversalTrace.Kind.BOX_NODE, Double.NaN, -1, -1, "", -1, false);
    }

    @Override public void boxTest(int child, boolean entered, double lo, double hi) {
        boxes.add(new TraversalTrace.BoxTest(child, entered, lo, hi));
        add(TraversalTrace.Kind.BOX_TEST, Double.NaN, -1, -1, "", -1, false);
    }

    @Override public void pushFar(int n, double lo, double hi) {
        stack.add(new TraversalTrace.Entry(n, lo, hi));
        TraversalTrace.Step last = steps.get(steps.size() - 1);
        if (last.kind() == TraversalTrace.Kind.BOX_TEST) {   // a hierarchy: the nearer box entered first, the other saved
            add(TraversalTrace.Kind.PUSH_FAR, Double.NaN, nearerBox(n), n, "nearer box, then the other", -1, false);
        } else {
            add(TraversalTrace.Kind.PUSH_FAR, last.tSplit(), last.near(), last.far(), last.visit(), -1, false);
        }
    }

    /** The box entered at this node other than {@code far}. */
    private int nearerBox(int far) {
        for (TraversalTrace.BoxTest b : boxes) if (b.entered() && b.node() != far) return b.node();
        return -1;
    }

    @Override public void pop(int n, double lo, double hi, boolean skipped) {
        if (!stack.isEmpty()) stack.remove(stack.size() - 1);
        at(n, lo, hi);
        tested.clear();
        boxes.clear();
        add(skipped ? TraversalTrace.Kind.SKIP : TraversalTrace.Kind.POP, Double.NaN, -1, -1, "", -1, false);
    }

    @Override public void leaf(int n, double lo, double hi, int count) {
        at(n, lo, hi);
        tested.clear();
        boxes.clear();
        add(TraversalTrace.Kind.LEAF, Double.NaN, -1, -1, "", -1, false);
    }

    @Override public void primitive(int primitive, boolean hit, double t) {
        tested.add(primitive);
        if (hit) {
            best = primitive;
            bestT = t;
        }
        add(TraversalTrace.Kind.TEST, Double.NaN, -1, -1, "", primitive, hit);
    }

    @Override public void mailboxed(int primitive) {
        add(TraversalTrace.Kind.MAILBOXED, Double.NaN, -1, -1, "", primitive, false);
    }

    @Override public void end(boolean found, Hit hit) {
        if (found) {
            best = hit.primitive;
            bestT = hit.t;
        }
        node = -1;            // done: no node is current, none of its boxes or objects under test
        tMin = tMax = Double.NaN;
        tested.clear();
        boxes.clear();
        add(TraversalTrace.Kind.END, Double.NaN, -1, -1, "", -1, found);
    }

    /** Sends each event to two listeners. */
    private record Both(TraversalListener a, TraversalListener b) implements TraversalListener {
        @Override public void begin(double lo, double hi) { a.begin(lo, hi); b.begin(lo, hi); }
        @Override public void missedScene() { a.missedScene(); b.missedScene(); }
        @Override public void interior(int n, int axis, double s, double lo, double hi, double ts, int near, int far, Visit v) {
            a.interior(n, axis, s, lo, hi, ts, near, far, v);
            b.interior(n, axis, s, lo, hi, ts, near, far, v);
        }
        @Override public void boxNode(int n, double lo, double hi) { a.boxNode(n, lo, hi); b.boxNode(n, lo, hi); }
        @Override public void boxTest(int n, boolean in, double lo, double hi) { a.boxTest(n, in, lo, hi); b.boxTest(n, in, lo, hi); }
        @Override public void pushFar(int n, double lo, double hi) { a.pushFar(n, lo, hi); b.pushFar(n, lo, hi); }
        @Override public void pop(int n, double lo, double hi, boolean s) { a.pop(n, lo, hi, s); b.pop(n, lo, hi, s); }
        @Override public void leaf(int n, double lo, double hi, int c) { a.leaf(n, lo, hi, c); b.leaf(n, lo, hi, c); }
        @Override public void primitive(int p, boolean h, double t) { a.primitive(p, h, t); b.primitive(p, h, t); }
        @Override public void mailboxed(int p) { a.mailboxed(p); b.mailboxed(p); }
        @Override public void end(boolean f, Hit h) { a.end(f, h); b.end(f, h); }
    }
}
