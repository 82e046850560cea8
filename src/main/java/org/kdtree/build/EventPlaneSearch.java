package org.kdtree.build;

/**
 * The sweep of the O(N log N) build: the node's events are already sorted, so each axis is
 * one pass. At each position the plane is offered with |T_L| (references starting before
 * it or lying in planes before it), |T_P| (lying in it) and |T_R| (ending after it), exactly
 * as {@link SortedPlaneSearch#sweep} counts them, so the costs and the choice agree bit for bit.
 */
final class EventPlaneSearch implements PlaneSearch {
    @Override public void search(BuildNode node, SahCost sah, SahSplit best) {
        if (!(node instanceof EventNode e))
            throw new IllegalArgumentException("the event search needs an EventNode (use SahBuilder with Algorithm.EVENT)");
        for (int axis = 0; axis < node.dimension(); axis++)
            sweep(sah, best, axis, node.size(), e.positions(), e.codes(), e.eventsFrom(axis), e.eventsTo(axis));
    }

    /**
     * The same search with one fork/join task per axis (for the big nodes at the top of a
     * parallel build). Each axis keeps its own first minimum; they are then combined in axis
     * order, keeping a later axis only if strictly cheaper: exactly the sequential choice.
     */
    static void searchAxesInParallel(EventNode e, SahCost sah, SahSplit best) {
        int k = e.dimension();
        SahSplit[] perAxis = new SahSplit[k];
        java.util.List<java.util.concurrent.ForkJoinTask<?>> tasks = new java.util.ArrayList<>();
        for (int a = 0; a < k; a++) {
            int axis = a;
            perAxis[a] = new SahSplit();
            tasks.add(java.util.concurrent.ForkJoinTask.adapt(() -> sweep(sah, perAxis[axis], axis, e.size(),
                    e.positions(), e.codes(), e.eventsFrom(axis), e.eventsTo(axis))));
        }
        java.util.concurrent.ForkJoinTask.invokeAll(tasks);
        for (SahSplit s : perAxis) best.keepIfCheaper(s);
    }

    /** One axis: events grouped by position; ends, planars and starts counted per group. */
    static void sweep(SahCost sah, SahSplit best, int axis, int n, double[] pos, int[] code, int from, int m) {
        int i = from;
        int nl = 0, nr = n;
        while (i < m) {
            double x = pos[i];
            int group = 0, pPlanar = 0, pStart = 0;
            for (; i < m && pos[i] == x; i++) {
                if (x == 0) x = Math.min(x, pos[i]);   // -0.0 if the group has one, as the other searches pick
                int kind = code[i] & 3;                 // END 0, PLANAR 1, START 2: counted without branches
                group++;
                pPlanar += kind & 1;
                pStart += kind >>> 1;
            }
            int pEnd = group - pPlanar - pStart;
            nr -= pPlanar + pEnd;
            best.offer(sah, axis, x, nl, pPlanar, nr);
            nl += pStart + pPlanar;
        }
    }
}
