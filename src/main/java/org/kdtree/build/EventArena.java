package org.kdtree.build;

import org.kdtree.geom.Box;

/**
 * Scratch memory of the O(N log N) build, one per thread of work (the whole build, or one
 * forked subtree), so that a split allocates no arrays.
 *
 * <p>The recursion is depth-first, so memory is kept per depth: a split at depth d writes both
 * children into level d + 1. While the left subtree is built (levels d + 2 and deeper), the
 * right child waits untouched in level d + 1; by the time another node writes to level d + 1,
 * every node that lived there is finished. A level is therefore overwritten, or replaced by
 * bigger arrays, only when all its earlier contents are dead, and nodes may keep direct
 * references to its arrays.
 *
 * <p>Peak memory is that of the plain recursion (which also keeps each pending right child),
 * without its garbage: the arrays are reused by every node of the same depth.
 */
final class EventArena {
    /** The arrays of one depth: references and the events of all axes. */
    static final class Level {
        int[] refs = new int[0];
        double[] pos = new double[0];
        int[] code = new int[0];

        /** Makes room for {@code refCount} references and {@code eventCount} events; old contents are dead. */
        void reserve(int refCount, int eventCount) {
            if (refs.length < refCount) refs = new int[grown(refs.length, refCount)];
            if (pos.length < eventCount) {
                int n = grown(pos.length, eventCount);
                pos = new double[n];
                code = new int[n];
            }
        }
    }

    private final int k;
    private final Level[] levels = new Level[KdTreeBuilder.DEPTH_LIMIT + 2];

    /** Per-split scratch: the parent's per-reference side and child index, the straddlers' events. */
    private int[] index = new int[0];
    private int[] straddlers = new int[0];
    private double[] straddlerBounds = new double[0];
    private double[] straddlePos = new double[0];
    private int[] straddleCode = new int[0];

    /** Boxes to clip a straddler into. */
    final Box clipLeft, clipRight;

    EventArena(int k) {
        this.k = k;
        this.clipLeft = new Box(k);
        this.clipRight = new Box(k);
    }

    int dimension() { return k; }

    /** The level of depth {@code depth}, with room for the given numbers of references and events. */
    Level level(int depth, int refCount, int eventCount) {
        Level l = levels[depth];
        if (l == null) levels[depth] = l = new Level();
        l.reserve(refCount, eventCount);
        return l;
    }

    /** Scratch of at least {@code n} ints for one reference each of the node being split. */
    int[] index(int n) {
        if (index.length < n) index = new int[grown(index.length, n)];
        return index;
    }

    /** Scratch of at least {@code n} ints for the child indices of straddlers. */
    int[] straddlers(int n) {
        if (straddlers.length < n) straddlers = new int[grown(straddlers.length, n)];
        return straddlers;
    }

    /** Scratch for the bounds of {@code n} straddlers, {@code 2 k} values each. */
    double[] straddlerBounds(int n) {
        if (straddlerBounds.length < 2 * k * n) straddlerBounds = new double[grown(straddlerBounds.length, 2 * k * n)];
        return straddlerBounds;
    }

    /** Scratch positions for at least {@code m} straddler events. */
    double[] straddlePositions(int m) {
        if (straddlePos.length < m) {
            straddlePos = new double[grown(straddlePos.length, m)];
            straddleCode = new int[straddlePos.length];
        }
        return straddlePos;
    }

    /** The codes matching {@link #straddlePositions} (call that first). */
    int[] straddleCodes() { return straddleCode; }

    private static int grown(int current, int needed) {
        return (int) Math.min(Integer.MAX_VALUE - 8, Math.max(needed, current + (current >> 1) + 16L));
    }
}
