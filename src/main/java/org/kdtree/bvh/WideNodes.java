package org.kdtree.bvh;

import java.util.Arrays;

/**
 * The binary tree collapsed to at most {@code width} children per node (the "wide" or
 * multi-branching BVH of Embree and of Wald, Benthin and Boulos 2008): each node keeps its
 * children's boxes side by side, one axis at a time, so a traversal tests them together.
 *
 * <p>One {@code int} array holds every node, {@link #stride} words each, so that a node is one
 * stretch of memory: for each axis {@code width} minima then {@code width} maxima, as floats
 * rounded outwards (a float box contains the double one: it only admits more rays, never
 * fewer, and halves the bytes a ray reads); then per child slot its reference, then its count.
 * A count is a leaf's primitive count (its primitives start at the reference in the leaf order),
 * 0 for an interior child (the reference is its wide node), or -1 for an unused slot (always
 * after the used ones).
 */
final class WideNodes {
    final int width, k;
    /** Words per node: 2 k width floats, width references, width counts. */
    final int stride;
    /** Offset of the references within a node (the counts follow them). */
    final int refs;
    /** Filled while the tree is laid out, then trimmed to the nodes made; not modified after. */
    int[] words;
    private int nodes;

    WideNodes(int k, int width, BuildNode root) {
        this.k = k;
        this.width = width;
        this.refs = 2 * k * width;
        this.stride = refs + 2 * width;
        // A wide node takes the place of up to width - 1 binary interior nodes: start from that, grow if needed.
        words = new int[stride * (root.size() / 2 / (width - 1) + 16)];
        add(root);
        words = Arrays.copyOf(words, stride * nodes);
    }

    /** Lays out the wide node whose children are those of {@code n}'s collapsed subtree; returns its index. */
    private int add(BuildNode n) {
        int id = nodes++;
        if (stride * nodes > words.length) words = Arrays.copyOf(words, Math.max(stride * nodes, words.length + words.length / 2));
        BuildNode[] kids = new BuildNode[width];
        int m = collapse(n, kids);
        int base = stride * id;
        for (int i = 0; i < width; i++) {
            boolean unused = i >= m || kids[i].isLeaf() && kids[i].count == 0;
            for (int a = 0; a < k; a++) {
                words[base + 2 * width * a + i] = Float.floatToRawIntBits(unused ? Float.POSITIVE_INFINITY : down(kids[i].box[a]));
                words[base + 2 * width * a + width + i] = Float.floatToRawIntBits(unused ? Float.NEGATIVE_INFINITY : up(kids[i].box[k + a]));
            }
            int ref = base + refs + i, count = ref + width;
            if (unused) {
                words[count] = -1;
            } else if (kids[i].isLeaf()) {
                words[ref] = kids[i].first;
                words[count] = kids[i].count;
            } else {
                int child = add(kids[i]);     // first: it may grow the array, which words[ref] = add(..) would have read before
                words[ref] = child;
                words[count] = 0;
            }
        }
        return id;
    }

    /** The largest float at most {@code v}. */
    static float down(double v) {
        float f = (float) v;
        return f > v ? Math.nextDown(f) : f;
    }

    /** The smallest float at least {@code v}. */
    static float up(double v) {
        float f = (float) v;
        return f < v ? Math.nextUp(f) : f;
    }

    /**
     * The children of a wide node: starting from {@code n}'s two (or {@code n} itself if it is a
     * leaf), the interior child of largest surface area is replaced by its own two until there
     * are {@code width} or only leaves. Returns how many.
     */
    private int collapse(BuildNode n, BuildNode[] kids) {
        if (n.isLeaf()) {
            kids[0] = n;
            return 1;
        }
        kids[0] = n.left;
        kids[1] = n.right;
        int m = 2;
        while (m < width) {
            int open = -1;
            double largest = -1;
            for (int i = 0; i < m; i++) {
                if (kids[i].isLeaf()) continue;
                double a = BoxArea.of(kids[i].box, 0, k);
                if (a > largest) {
                    largest = a;
                    open = i;
                }
            }
            if (open < 0) break;
            BuildNode o = kids[open];
            kids[open] = o.left;
            kids[m++] = o.right;
        }
        return m;
    }

    int nodeCount() { return nodes; }

    long memoryBytes() {
        return 4L * words.length;
    }
}
