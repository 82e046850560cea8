package org.kdtree.accel;

/**
 * The stack of a listening traversal: the far children saved for later, each with the ray's
 * interval in it, and the rule for taking the next one (a saved child that starts beyond the hit
 * found so far cannot hold anything closer, and is dropped). The kd-tree's and the bounding
 * volume hierarchy's listening loops share it; each reports its pushes and pops to its listener.
 * Not thread safe: one per traversal object.
 */
public final class TraversalStack {
    private final int[] node;
    private final double[] min, max;
    private int size;
    /** The entry taken last by {@link #popNext}. */
    private int top;
    private double topMin, topMax;

    /**
     * A stack for a structure of depth {@code depth - 2} at the most.
     *
     * @param depth the entries it can hold
     */
    public TraversalStack(int depth) {
        node = new int[depth];
        min = new double[depth];
        max = new double[depth];
    }

    /** Empties it, for a new ray. */
    public void clear() { size = 0; }

    /**
     * Saves a far child, with the ray's interval in it, and tells {@code l}.
     *
     * @param far  the child's node
     * @param tMin where the ray enters it
     * @param tMax where the ray leaves it
     * @param l    the traversal's listener
     */
    public void push(int far, double tMin, double tMax, TraversalListener l) {
        node[size] = far;
        min[size] = tMin;
        max[size++] = tMax;
        l.pushFar(far, tMin, tMax);
    }

    /**
     * Takes the next saved child that can still hold a hit closer than {@code hitT}, telling
     * {@code l} of each one taken or dropped; {@link #node()}, {@link #tMin()} and {@link #tMax()}
     * then give it.
     *
     * @param prune whether to drop children that start beyond {@code hitT} (a closest-hit query)
     * @param hitT  the closest hit so far (infinity if none)
     * @param slack the traversal's relative slack on interval comparisons
     * @param l     the traversal's listener
     * @return false when the stack is empty
     */
    public boolean popNext(boolean prune, double hitT, double slack, TraversalListener l) {
        while (size > 0) {
            size--;
            top = node[size];
            topMin = min[size];
            topMax = max[size];
            boolean skip = prune && topMin > hitT + Math.abs(hitT) * slack;
            l.pop(top, topMin, topMax, skip);
            if (!skip) return true;
        }
        return false;
    }

    /** {@return the node taken last} */
    public int node() { return top; }

    /** {@return where the ray enters the node taken last} */
    public double tMin() { return topMin; }

    /** {@return where the ray leaves the node taken last} */
    public double tMax() { return topMax; }
}
