package org.kdtree.accel;

/**
 * Per-ray (or accumulated) traversal statistics: a {@link TraversalListener} that counts.
 * Pass one to a query to fill it; queries without one pay nothing. Counts accumulate until
 * {@link #reset()}.
 */
public final class TraversalStats implements TraversalListener {
    /** Nodes visited, interior and leaves. */
    public long nodes;
    /** Leaves visited (empty ones included). */
    public long leaves;
    /** Ray/primitive tests performed. */
    public long primitiveTests;
    /** Tests that found an intersection (within the ray's range, closer than the best so far). */
    public long hits;
    /** Repeated references skipped by mailboxing. */
    public long mailboxed;
    /** Bounding boxes tested (a bounding volume hierarchy's; a kd-tree tests none). */
    public long boxTests;
    /** Rays traced. */
    public long rays;

    /**
     * Sets every count to zero.
     *
     * @return these statistics
     */
    public TraversalStats reset() {
        nodes = leaves = primitiveTests = hits = mailboxed = boxTests = rays = 0;
        return this;
    }

    /**
     * Adds another's counts to these.
     *
     * @param o the counts to add
     * @return these statistics
     */
    public TraversalStats add(TraversalStats o) {
        nodes += o.nodes; leaves += o.leaves; primitiveTests += o.primitiveTests;
        hits += o.hits; mailboxed += o.mailboxed; boxTests += o.boxTests; rays += o.rays;
        return this;
    }

    @Override public void begin(double tMin, double tMax) { rays++; }
    @Override public void missedScene() { rays++; }
    @Override public void interior(int node, int axis, double split, double tMin, double tMax, double tSplit,
                                   int near, int far, Visit visit) { nodes++; }
    @Override public void boxNode(int node, double tMin, double tMax) { nodes++; }
    @Override public void boxTest(int node, boolean entered, double tMin, double tMax) { boxTests++; }
    @Override public void leaf(int node, double tMin, double tMax, int count) { nodes++; leaves++; }
    @Override public void primitive(int primitive, boolean hit, double t) {
        primitiveTests++;
        if (hit) hits++;
    }
    @Override public void mailboxed(int primitive) { mailboxed++; }

    @Override public String toString() {
        return String.format(java.util.Locale.ROOT,
                "rays=%d nodes=%d leaves=%d primitiveTests=%d hits=%d mailboxed=%d boxTests=%d", rays, nodes, leaves,
                primitiveTests, hits, mailboxed, boxTests);
    }
}
