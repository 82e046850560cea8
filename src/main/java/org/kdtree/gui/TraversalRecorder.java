package org.kdtree.gui;

import java.util.ArrayList;
import java.util.List;
import org.kdtree.geom.Ray;
import org.kdtree.shape.Scene2D;
import org.kdtree.traverse.Hit;
import org.kdtree.traverse.Shape2DIntersector;
import org.kdtree.traverse.TraversalListener;
import org.kdtree.traverse.TraversalStats;
import org.kdtree.traverse.Traverser;
import org.kdtree.tree.KdTree;

/**
 * Records the real traversal ({@link Traverser#closestHit} with a {@link TraversalListener})
 * into a {@link TraversalTrace}: the stepper replays what the library did, it does not
 * traverse on its own.
 */
final class TraversalRecorder implements TraversalListener {
    private final List<TraversalTrace.Step> steps = new ArrayList<>();
    private final List<TraversalTrace.Entry> stack = new ArrayList<>();
    private final List<Integer> tested = new ArrayList<>();
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
        if (ray == null) return TraversalTrace.EMPTY;
        Traverser traverser = new Traverser(tree, new Shape2DIntersector(scene));
        TraversalRecorder rec = new TraversalRecorder();
        TraversalStats stats = new TraversalStats();
        Hit hit = new Hit();
        boolean found = traverser.closestHit(new Ray(2).set(ray[0], ray[1], ray[2], ray[3]), 0, Double.POSITIVE_INFINITY,
                hit, new Both(rec, stats));
        return new TraversalTrace(List.copyOf(rec.steps), stats.nodes, stats.leaves, stats.primitiveTests,
                found ? hit.primitive : -1, found ? hit.t : Double.NaN);
    }

    private void add(TraversalTrace.Kind kind, double tSplit, int near, int far, String visit, int object, boolean hit) {
        steps.add(new TraversalTrace.Step(kind, node, tMin, tMax, tSplit, near, far, visit, List.copyOf(stack),
                List.copyOf(tested), object, hit, best, bestT));
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

    @Override public void pushFar(int n, double lo, double hi) {
        stack.add(new TraversalTrace.Entry(n, lo, hi));
        TraversalTrace.Step last = steps.get(steps.size() - 1);
        add(TraversalTrace.Kind.PUSH_FAR, last.tSplit(), last.near(), last.far(), last.visit(), -1, false);
    }

    @Override public void pop(int n, double lo, double hi, boolean skipped) {
        if (!stack.isEmpty()) stack.remove(stack.size() - 1);
        at(n, lo, hi);
        tested.clear();
        add(skipped ? TraversalTrace.Kind.SKIP : TraversalTrace.Kind.POP, Double.NaN, -1, -1, "", -1, false);
    }

    @Override public void leaf(int n, double lo, double hi, int count) {
        at(n, lo, hi);
        tested.clear();
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
        node = -1;
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
        @Override public void pushFar(int n, double lo, double hi) { a.pushFar(n, lo, hi); b.pushFar(n, lo, hi); }
        @Override public void pop(int n, double lo, double hi, boolean s) { a.pop(n, lo, hi, s); b.pop(n, lo, hi, s); }
        @Override public void leaf(int n, double lo, double hi, int c) { a.leaf(n, lo, hi, c); b.leaf(n, lo, hi, c); }
        @Override public void primitive(int p, boolean h, double t) { a.primitive(p, h, t); b.primitive(p, h, t); }
        @Override public void mailboxed(int p) { a.mailboxed(p); b.mailboxed(p); }
        @Override public void end(boolean f, Hit h) { a.end(f, h); b.end(f, h); }
    }
}
