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
 * after the used ones). {@link RayKernel#SPARE} words follow the last node, so that a vector
 * kernel may load whole vectors from any node's rows.
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

    /** The binary tree collapsed from. */
    private final Bvh bvh;

    WideNodes(Bvh bvh, int width) {
        this.bvh = bvh;
        this.k = bvh.dimension();
        this.width = width;
        this.refs = 2 * k * width;
        this.stride = refs + 2 * width;
        // A wide node takes the place of up to width - 1 binary interior nodes: start from that, grow if needed.
        words = new int[stride * (bvh.nodeCount() / 2 / (width - 1) + 16)];
        add(0);
        words = Arrays.copyOf(words, stride * nodes + RayKernel.SPARE);
    }

    /** Lays out the wide node whose children are those of binary node {@code n}'s collapsed subtree; returns its index. */
    private int add(int n) {
        int id = nodes++;
        if (stride * nodes > words.length) words = Arrays.copyOf(words, Math.max(stride * nodes, words.length + words.length / 2));
        int[] kids = new int[width];
        int m = collapse(n, kids);
        int base = stride * id;
        for (int i = 0; i < width; i++) {
            boolean unused = i >= m || bvh.isLeaf(kids[i]) && bvh.leafSize(kids[i]) == 0;
            for (int a = 0; a < k; a++) {
                words[base + 2 * width * a + i] = Float.floatToRawIntBits(unused ? Float.POSITIVE_INFINITY : down(bvh.min(kids[i], a)));
                words[base + 2 * width * a + width + i] = Float.floatToRawIntBits(unused ? Float.NEGATIVE_INFINITY : up(bvh.max(kids[i], a)));
            }
            boolean leaf = unused || bvh.isLeaf(kids[i]);
            int child = leaf ? 0 : add(kids[i]);     // first: it may grow the array, which words[ref] = add(..) would have read before
            int ref = base + refs + i;
            words[ref] = unused ? 0 : leaf ? bvh.leafStart(kids[i]) : child;
            words[ref + width] = unused ? -1 : leaf ? bvh.leafSize(kids[i]) : 0;
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
     * The children of a wide node: starting from binary node {@code n}'s two (or {@code n} itself
     * if it is a leaf), the interior child of largest surface area is replaced by its own two
     * until there are {@code width} or only leaves. Returns how many.
     */
    private int collapse(int n, int[] kids) {
        if (bvh.isLeaf(n)) {
            kids[0] = n;
            return 1;
        }
        kids[0] = bvh.left(n);
        kids[1] = bvh.right(n);
        int m = 2;
        double[] box = bvh.boxArray();
        while (m < width) {
            int open = -1;
            double largest = -1;
            for (int i = 0; i < m; i++) {
                if (bvh.isLeaf(kids[i])) continue;
                double a = BoxArea.of(box, 2 * k * kids[i], k);
                if (a > largest) {
                    largest = a;
                    open = i;
                }
            }
            if (open < 0) break;
            int o = kids[open];
            kids[open] = bvh.left(o);
            kids[m++] = bvh.right(o);
        }
        return m;
    }

    int nodeCount() { return nodes; }

    long memoryBytes() { return 4L * words.length; }
}
