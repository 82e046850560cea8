package org.kdtree.bvh;

import java.util.Arrays;

/**
 * The binary tree collapsed to at most {@code width} children per node (the "wide" or
 * multi-branching BVH of Embree and of Wald, Benthin and Boulos 2008): each node keeps its
 * children's boxes side by side, one axis at a time, so a traversal tests them together.
 *
 * <p>Per node, {@code box} holds for each axis {@code width} minima then {@code width} maxima;
 * per child slot, {@code count} is a leaf's primitive count (its primitives start at
 * {@code ref} in the leaf order), 0 for an interior child (the wide node {@code ref}), or -1 for
 * an unused slot (always after the used ones).
 */
final class WideNodes {
    final int width, k;
    /** Filled while the tree is laid out, then trimmed to the nodes made; not modified after. */
    double[] box;
    int[] ref, count;
    private int nodes;

    WideNodes(int k, int width, BuildNode root) {
        this.k = k;
        this.width = width;
        int capacity = Math.max(1, root.size());  // a wide tree has fewer nodes than the binary one
        double[] b = new double[2 * k * width * capacity];
        int[] r = new int[width * capacity], c = new int[width * capacity];
        this.box = b;
        this.ref = r;
        this.count = c;
        add(root);
        box = Arrays.copyOf(box, 2 * k * width * nodes);
        ref = Arrays.copyOf(ref, width * nodes);
        count = Arrays.copyOf(count, width * nodes);
    }

    /** Lays out the wide node whose children are those of {@code n}'s collapsed subtree; returns its index. */
    private int add(BuildNode n) {
        int id = nodes++;
        BuildNode[] kids = new BuildNode[width];
        int m = collapse(n, kids);
        int slot = id * width, base = 2 * k * width * id;
        for (int i = 0; i < width; i++) {
            if (i >= m || kids[i].isLeaf() && kids[i].count == 0) {
                count[slot + i] = -1;
                for (int a = 0; a < k; a++) {
                    box[base + 2 * width * a + i] = Double.POSITIVE_INFINITY;
                    box[base + 2 * width * a + width + i] = Double.NEGATIVE_INFINITY;
                }
                continue;
            }
            BuildNode c = kids[i];
            for (int a = 0; a < k; a++) {
                box[base + 2 * width * a + i] = c.box[a];
                box[base + 2 * width * a + width + i] = c.box[k + a];
            }
            if (c.isLeaf()) {
                count[slot + i] = c.count;
                ref[slot + i] = c.first;
            } else {
                count[slot + i] = 0;
                ref[slot + i] = add(c);
            }
        }
        return id;
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
        return 8L * box.length + 4L * (ref.length + count.length);
    }
}
