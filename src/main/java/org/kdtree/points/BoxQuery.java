package org.kdtree.points;

import org.kdtree.kdtree.Nodes;

/**
 * All points inside an axis-aligned box (faces included), by increasing index. One instance per
 * thread, reused across queries; its stack is sized once from the tree's depth and its result
 * array grows only when a query finds more points than any before it. The {@link PointTree} is
 * shared.
 *
 * <p>A child is visited when the box reaches its side of the split plane; a point lying in the
 * plane may be in either child, and both voxels include the plane, so nothing is missed.
 */
public final class BoxQuery {
    private final PointTree points;
    private final int k;
    /** The tree's nodes and references ({@link org.kdtree.kdtree.KdTree#nodeArray()}), read with {@link Nodes}. */
    private final int[] nodes, refs;
    /** The tree's {@link org.kdtree.kdtree.KdTree#axisBits()}, which {@link Nodes} decodes a word with. */
    private final int bits;
    private final double[] coords;
    private final int[] stack;
    private int[] found = new int[64];
    private int count, leavesVisited;

    /** @param points the tree of points to query, shared with other queries */
    public BoxQuery(PointTree points) {
        this.points = points;
        k = points.dimension();
        nodes = points.tree().nodeArray();
        bits = points.tree().axisBits();
        refs = points.tree().refArray();
        coords = points.leafCoordArray();
        stack = new int[points.maxDepth() + 2];
    }

    /** {@return the leaves scanned by the last query} */
    public int leavesVisited() { return leavesVisited; }

    /**
     * The points {@code p} with {@code min[a] <= p[a] <= max[a]} on every axis, by increasing
     * index: the first {@code min(count, indices.length)} go into {@code indices}. Returns the
     * count of all such points (0 when {@code min > max} on some axis).
     *
     * @param min     the box's lower corner, k coordinates, no NaN
     * @param max     the box's upper corner, k coordinates, no NaN
     * @param indices receives the points' indices
     * @return how many points are inside the box, even when more than {@code indices.length}
     */
    public int inside(double[] min, double[] max, int[] indices) {
        check(min, "min");
        check(max, "max");
        count = 0;
        leavesVisited = 0;
        if (points.size() > 0) search(min, max);
        PairSort.sort(found, count);
        System.arraycopy(found, 0, indices, 0, Math.min(count, indices.length));
        return count;
    }

    private void search(double[] min, double[] max) {
        int sp = 0, node = 0;
        while (true) {
            int w = Nodes.word(nodes, node);
            while (!Nodes.isLeaf(w, bits)) {
                int axis = Nodes.axis(w, bits);
                double xi = Nodes.split(nodes, node);
                boolean left = min[axis] <= xi, right = max[axis] >= xi;
                if (left && right) stack[sp++] = Nodes.rightChild(w, bits);
                if (left) node = Nodes.leftChild(node);
                else if (right) node = Nodes.rightChild(w, bits);
                else break; // an empty box (min > max) reaches neither side
                w = Nodes.word(nodes, node);
            }
            if (Nodes.isLeaf(w, bits)) scanLeaf(Nodes.leafStart(nodes, node), Nodes.leafSize(w, bits), min, max);
            if (sp == 0) return;
            node = stack[--sp];
        }
    }

    private void scanLeaf(int first, int count, double[] min, double[] max) {
        leavesVisited++;
        for (int j = first; j < first + count; j++) {
            if (inside(j * k, min, max)) add(refs[j]);
        }
    }

    private boolean inside(int base, double[] min, double[] max) {
        for (int a = 0; a < k; a++) {
            double c = coords[base + a];
            if (c < min[a] || c > max[a]) return false;
        }
        return true;
    }

    private void add(int point) {
        if (count == found.length) found = java.util.Arrays.copyOf(found, 2 * count);
        found[count++] = point;
    }

    private void check(double[] corner, String name) {
        if (corner.length != k) throw new IllegalArgumentException(name + " corner is " + corner.length + "-D, points " + k + "-D");
        for (int a = 0; a < k; a++)
            if (Double.isNaN(corner[a])) throw new IllegalArgumentException(name + " corner coordinate " + a + " is NaN");
    }
}
