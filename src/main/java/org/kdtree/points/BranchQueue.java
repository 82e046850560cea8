package org.kdtree.points;

/**
 * The branches a best-bin-first search has put aside (FLANN's approximate search, after Beis and
 * Lowe): far children, each with its voxel's accumulated distance and the per-axis offsets that
 * distance came from, so the search can resume there incrementally. A binary min-heap on the
 * distance over slots that are filled in order and reused by the next query; the arrays grow
 * only when a query puts aside more branches than any before it.
 */
final class BranchQueue {
    private final int k;
    private int[] node = new int[64];
    private double[] distance = new double[64];
    private double[] offsets;
    private int[] heap = new int[64];
    private int slots, size;

    BranchQueue(int k) {
        this.k = k;
        offsets = new double[64 * k];
    }

    void clear() {
        slots = 0;
        size = 0;
    }

    boolean isEmpty() { return size == 0; }

    /** The smallest distance put aside (call only when not empty). */
    double nearestDistance() { return distance[heap[0]]; }

    /** Puts aside {@code n}, at accumulated distance {@code rd}, with the offsets {@code off} of its voxel. */
    void push(int n, double rd, double[] off) {
        if (slots == node.length) grow();
        int s = slots++;
        node[s] = n;
        distance[s] = rd;
        System.arraycopy(off, 0, offsets, s * k, k);
        int i = size++;
        heap[i] = s;
        while (i > 0) {
            int parent = (i - 1) / 2;
            if (distance[heap[parent]] <= rd) break;
            heap[i] = heap[parent];
            heap[parent] = s;
            i = parent;
        }
    }

    /** Takes the nearest branch out, writes its offsets into {@code off} and returns its node. */
    int popNearest(double[] off) {
        int s = heap[0];
        heap[0] = heap[--size];
        siftDown();
        System.arraycopy(offsets, s * k, off, 0, k);
        return node[s];
    }

    private void siftDown() {
        int i = 0;
        while (true) {
            int c = 2 * i + 1;
            if (c >= size) return;
            if (c + 1 < size && distance[heap[c + 1]] < distance[heap[c]]) c++;
            if (distance[heap[c]] >= distance[heap[i]]) return;
            int t = heap[i];
            heap[i] = heap[c];
            heap[c] = t;
            i = c;
        }
    }

    private void grow() {
        int n = node.length * 2;
        node = java.util.Arrays.copyOf(node, n);
        distance = java.util.Arrays.copyOf(distance, n);
        heap = java.util.Arrays.copyOf(heap, n);
        offsets = java.util.Arrays.copyOf(offsets, n * k);
    }
}
