package org.kdtree.gui;

import java.util.BitSet;
import java.util.List;

/**
 * One k-nearest-neighbour search over the workbench's tree, recorded event by event so that the
 * nearest-neighbour stepper can go forward and back: each {@link Step} is the state of the search
 * just after one event (the node entered or pruned with its distance bound, the object tested and
 * its distance, the list of the k best so far).
 *
 * @param steps   the steps, in order
 * @param query   the query point {x, y}
 * @param k       how many neighbours were asked for
 * @param nodes   nodes entered (interior and leaves)
 * @param leaves  leaves entered
 * @param pruned  nodes pruned because their voxel lies beyond the k-th best distance
 * @param tests   object distance tests performed (each object at most once)
 * @param result  the k nearest objects (fewer if the scene has fewer), nearest first
 */
record NearestTrace(List<Step> steps, double[] query, int k, long nodes, long leaves, long pruned, long tests,
                           List<Neighbour> result) {
    /** What happened at a step. */
    public enum Kind {
        /** The search starts at the root. */
        BEGIN,
        /** An interior node is entered: its near child is searched first, then the far one. */
        INTERIOR,
        /** A leaf is entered: its objects are tested. */
        LEAF,
        /** A node is skipped: its voxel lies farther than the k-th best distance. */
        PRUNE,
        /** An object's distance is computed. */
        TEST,
        /** An object already tested in another leaf is skipped (mailbox). */
        MAILBOXED,
        /** The search is done. */
        END
    }

    /** An object among the best so far, with its exact distance to the query. */
    public record Neighbour(int object, double distance) {
    }

    /**
     * The state after one event.
     *
     * @param kind     the event
     * @param node     the node entered or pruned, or whose leaf holds the tested object (-1 at BEGIN and END)
     * @param bound    the distance from the query to the node's voxel (NaN at TEST, MAILBOXED, END)
     * @param near     an interior node's near child, the side of the split plane the query is on (-1 otherwise)
     * @param far      an interior node's far child (-1 otherwise)
     * @param object   the object of a TEST or MAILBOXED step (-1 otherwise)
     * @param distance the tested object's distance (NaN unless TEST; +infinity for a zero-area shape)
     * @param closestX the x of the tested object's point closest to the query (NaN unless a finite TEST)
     * @param closestY its y
     * @param improved whether the tested object entered the list of the k best
     * @param best     the k best so far, nearest first
     * @param kth      the k-th best distance so far: the search's radius (+infinity while fewer than k are known)
     */
    public record Step(Kind kind, int node, double bound, int near, int far, int object, double distance,
                       double closestX, double closestY, boolean improved, List<Neighbour> best, double kth) {
    }

    /** A trace with no steps, for when there is no query. */
    public static final NearestTrace EMPTY = new NearestTrace(List.of(), null, 0, 0, 0, 0, 0, List.of());

    /** {@return the number of steps} */
    public int size() { return steps.size(); }

    /**
     * {@return step {@code i}, 0 first}
     *
     * @param i the step's index
     */
    public Step step(int i) { return steps.get(i); }

    /**
     * {@return the nodes entered in steps 0 .. {@code last}}
     *
     * @param last the last step counted
     */
    public BitSet enteredUpTo(int last) {
        return upTo(last, false);
    }

    /**
     * {@return the nodes pruned in steps 0 .. {@code last}}
     *
     * @param last the last step counted
     */
    public BitSet prunedUpTo(int last) {
        return upTo(last, true);
    }

    private BitSet upTo(int last, boolean pruned) {
        BitSet out = new BitSet();
        for (int i = 0; i <= last && i < steps.size(); i++) {
            Step s = steps.get(i);
            boolean entered = s.kind == Kind.INTERIOR || s.kind == Kind.LEAF;
            if (pruned ? s.kind == Kind.PRUNE : entered) out.set(s.node);
        }
        return out;
    }
}
