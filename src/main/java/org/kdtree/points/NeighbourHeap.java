package org.kdtree.points;

/**
 * The k best candidates of a nearest-neighbour search so far: a bounded max-heap of (accumulated
 * distance, point index) ordered by distance, then index, so that the worst candidate, the one
 * a closer point evicts, sits at the root. Ordering by index on equal distances makes the
 * result deterministic, the same as sorting all points (brute force) would give.
 */
final class NeighbourHeap {
    private double[] key = new double[0];
    private int[] index = new int[0];
    private int size, k;

    /** Empties the heap for a search of {@code k} neighbours (grows its arrays when k grows). */
    void reset(int k) {
        if (key.length < k) {
            key = new double[k];
            index = new int[k];
        }
        this.k = k;
        size = 0;
    }

    int size() { return size; }

    /** The accumulated distance a point must not exceed to enter: the worst kept, or infinity while not full. */
    double worst() {
        return size < k ? Double.POSITIVE_INFINITY : key[0];
    }

    /** Keeps the point if it is among the k best so far. */
    void offer(double acc, int point) {
        if (size < k) {
            int i = size++;
            key[i] = acc;
            index[i] = point;
            siftUp(i);
        } else if (PairSort.after(key[0], index[0], acc, point)) {
            key[0] = acc;
            index[0] = point;
            PairSort.siftDown(key, index, 0, size);
        }
    }

    private void siftUp(int i) {
        while (i > 0) {
            int parent = (i - 1) / 2;
            if (!PairSort.after(key[i], index[i], key[parent], index[parent])) return;
            PairSort.swap(key, index, i, parent);
            i = parent;
        }
    }

    /**
     * Writes the candidates nearest first into {@code indices} and, unless null, their true
     * distances into {@code distances}, leaving out those farther than {@code maxDistance}
     * (the search's bound carries a little slack); returns how many were written. Empties the heap.
     */
    int drainSorted(Metric metric, double maxDistance, int[] indices, double[] distances) {
        PairSort.sort(key, index, size);
        int n = 0;
        for (int i = 0; i < size; i++) {
            double d = metric.distance(key[i]);
            if (d > maxDistance) break;
            indices[n] = index[i];
            if (distances != null) distances[n] = d;
            n++;
        }
        size = 0;
        return n;
    }
}
