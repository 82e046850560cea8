package org.kdtree.gui;

import java.util.List;

/**
 * One ray's traversal, recorded event by event so that the stepper can go forward and back:
 * each {@link Step} is the state of Algorithm 2 just after one event (current node, interval,
 * tSplit, near and far child, the stack, the primitives tested in the current leaf, the best
 * hit so far). A bounding volume hierarchy's traversal has box steps in place of the split
 * plane's: {@link Kind#BOX_NODE} and {@link Kind#BOX_TEST}, with the boxes tested at the node.
 *
 * @param steps      the steps, in order
 * @param nodes      nodes visited (interior and leaves)
 * @param leaves     leaves visited
 * @param tests      ray/object tests performed
 * @param boxTests   ray/box tests performed (a hierarchy's; 0 in a kd-tree)
 * @param hitObject  the object finally hit, or -1
 * @param hitT       its ray parameter (NaN without a hit)
 */
record TraversalTrace(List<Step> steps, long nodes, long leaves, long tests, long boxTests, int hitObject, double hitT) {
    /** What happened at a step. */
    public enum Kind {
        /** The ray enters the scene box. */
        BEGIN,
        /** The ray misses the scene box. */
        MISSED_SCENE,
        /** An interior node: tSplit, the near and far children, and which the ray visits. */
        INTERIOR,
        /** A hierarchy's interior node: its children's boxes are tested next. */
        BOX_NODE,
        /** A hierarchy's child box is tested: entered over an interval, or missed. */
        BOX_TEST,
        /** The far child is saved on the stack. */
        PUSH_FAR,
        /** A saved node is taken from the stack. */
        POP,
        /** A saved node is dropped: it lies beyond the closest hit. */
        SKIP,
        /** A leaf is reached. */
        LEAF,
        /** An object of the leaf is tested. */
        TEST,
        /** An object already tested for this ray is not tested again. */
        MAILBOXED,
        /** The traversal is over. */
        END
    }

    /** A node saved on the stack with its interval. */
    public record Entry(int node, double tMin, double tMax) {
    }

    /**
     * A hierarchy's child box tested against the ray.
     *
     * @param node    the child
     * @param entered whether the ray enters it (before the closest hit so far)
     * @param tMin    where the ray enters it
     * @param tMax    where it leaves
     */
    public record BoxTest(int node, boolean entered, double tMin, double tMax) {
    }

    /**
     * The state after one event.
     *
     * @param kind     the event
     * @param node     the current node (-1 before the root and after the end)
     * @param tMin     the ray's entry into the current node
     * @param tMax     the ray's exit from it
     * @param tSplit   where the ray meets the node's split plane (NaN unless at an interior node)
     * @param near     the near child (-1 unless at an interior node)
     * @param far      the far child (-1 unless at an interior node)
     * @param visit    which children the ray visits: "near", "far", "both", "both (in plane)", or ""
     * @param stack    the stack, bottom first
     * @param tested   objects tested in the current leaf so far
     * @param boxes    a hierarchy's child boxes tested at the current node so far (empty in a kd-tree)
     * @param object   the object of a TEST or MAILBOXED step (-1 otherwise)
     * @param hit      whether that test hit
     * @param bestObject the closest object hit so far, or -1
     * @param bestT    its t (NaN if none)
     */
    public record Step(Kind kind, int node, double tMin, double tMax, double tSplit, int near, int far, String visit,
                       List<Entry> stack, List<Integer> tested, List<BoxTest> boxes, int object, boolean hit, int bestObject, double bestT) {
    }

    /** A trace with no steps, for when there is no ray. */
    public static final TraversalTrace EMPTY = new TraversalTrace(List.of(), 0, 0, 0, 0, -1, Double.NaN);

    /** {@return the number of steps} */
    public int size() { return steps.size(); }

    /**
     * {@return step {@code i}, 0 first}
     *
     * @param i the step's index
     */
    public Step step(int i) { return steps.get(i); }
}
