package org.kdtree.kdtree;

/**
 * The SAH's O(N log N) plane search (Wald and Havran 2006, section 4.3): the node's events,
 * sorted once where the node was turned into events and kept sorted by every split since
 * ({@link NodeStore#EVENTS}), swept once per axis. At each position the plane is offered with
 * |T_L| (references starting before it or lying in planes before it), |T_P| (lying in it) and
 * |T_R| (ending after it), as {@link SortedPlaneSearch#sweep} counts them: the same candidates in
 * the same order, so the same plane. Linear in the node's events, and allocates nothing.
 */
final class EventSweep implements PlaneSearch {
    static final EventSweep INSTANCE = new EventSweep();

    private EventSweep() {
    }

    @Override public void search(BuildNode node, SahCost sah, SahSplit best) {
        NodeStore store = node.store();
        int d = node.level(), c = node.child(), n = node.size();
        store.events(d, c);
        double[] pos = store.positions(d);
        int[] code = store.codes(d), meta = store.eventMeta(d);
        int at = store.metaAt(c);
        for (int axis = 0; axis < store.k; axis++)
            sweep(sah, best, axis, n, pos, code, meta[at + 1 + 2 * axis], meta[at + 2 + 2 * axis]);
    }

    /** One axis: the events {@code [from, to)}, grouped by position; counted without branches. */
    private static void sweep(SahCost sah, SahSplit best, int axis, int n, double[] pos, int[] code, int from, int to) {
        int nl = 0, nr = n, i = from;
        while (i < to) {
            double x = pos[i];
            int group = 0, planar = 0, start = 0;
            for (; i < to && pos[i] == x; i++) {
                if (x == 0) x = Math.min(x, pos[i]);   // -0.0 if the group has one, as the other searches pick
                int kind = EventCode.kind(code[i]);    // END 0, PLANAR 1, START 2
                group++;
                planar += kind & 1;
                start += kind >>> 1;
            }
            nr -= group - start;
            best.offer(sah, axis, x, nl, planar, nr);
            nl += start + planar;
        }
    }
}
