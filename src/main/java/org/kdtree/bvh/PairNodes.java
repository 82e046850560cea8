package org.kdtree.bvh;

/**
 * The binary tree of a 3-D {@link Bvh} in one cache line per node: each record is 16 {@code int}
 * words, 64 bytes, and holds both children's boxes, so that one memory read gives a traversal
 * everything it needs to choose between them (tinybvh's "BVH_SoA"-free binary layout, Wald's
 * "both children in the parent").
 *
 * <p>Record {@code n} starts at word {@code 16 n}:
 * <pre>
 *   0..5    left child's box:  min x, y, z, max x, y, z   (floats, rounded outwards)
 *   6..11   right child's box: min x, y, z, max x, y, z
 *   12, 13  left child:  reference, count
 *   14, 15  right child: reference, count
 * </pre>
 * A count above 0 is a leaf's primitive count, and the reference is where its primitives start
 * in the leaf order; a count of 0 is an interior child, and the reference is its record. A
 * child that is an empty leaf gets an inverted box (+infinity to -infinity), which no ray enters.
 * The floats contain the double boxes ({@link WideNodes#down}, {@link WideNodes#up}): a box only
 * grows, so it admits more rays, never fewer. Records are in depth-first order, each interior
 * node's left child's record right after its own. A hierarchy whose root is a leaf gets one
 * record whose right child is empty.
 */
final class PairNodes {
    /** Words per record. */
    static final int STRIDE = 16;
    /** Offset of the left child's box; the right child's is at {@link #RIGHT}. */
    static final int LEFT = 0, RIGHT = 6;
    /** Offset of the left child's reference and count (the right child's follow). */
    static final int LINKS = 12;

    /** The records; not modified after construction. */
    final int[] words;

    PairNodes(Bvh bvh) {
        int interior = 0;
        for (int n = 0; n < bvh.nodeCount(); n++) if (!bvh.isLeaf(n)) interior++;
        words = new int[STRIDE * Math.max(1, interior)];
        if (bvh.isLeaf(0)) {
            child(bvh, 0, 0, 0, 1);
            empty(0, 1);
        } else {
            layOut(bvh, 0, 0, 1);
        }
    }

    /** Writes binary node {@code n}'s record at {@code id}, its descendants from {@code next}; returns the next free record. */
    private int layOut(Bvh bvh, int n, int id, int next) {
        int l = bvh.left(n), r = bvh.right(n);
        int after = next;
        int leftRecord = -1, rightRecord = -1;
        if (!bvh.isLeaf(l)) { leftRecord = after; after = layOut(bvh, l, after, after + 1); }
        if (!bvh.isLeaf(r)) { rightRecord = after; after = layOut(bvh, r, after, after + 1); }
        child(bvh, id, 0, l, leftRecord);
        child(bvh, id, 1, r, rightRecord);
        return after;
    }

    /** Writes child {@code side} (0 left, 1 right) of record {@code id}: binary node {@code c}, whose record (if interior) is {@code record}. */
    private void child(Bvh bvh, int id, int side, int c, int record) {
        int base = STRIDE * id, box = base + (side == 0 ? LEFT : RIGHT), link = base + LINKS + 2 * side;
        if (bvh.isLeaf(c) && bvh.leafSize(c) == 0) {
            empty(id, side);
            return;
        }
        for (int a = 0; a < 3; a++) {
            words[box + a] = Float.floatToRawIntBits(WideNodes.down(bvh.min(c, a)));
            words[box + 3 + a] = Float.floatToRawIntBits(WideNodes.up(bvh.max(c, a)));
        }
        if (bvh.isLeaf(c)) {
            words[link] = bvh.leafStart(c);
            words[link + 1] = bvh.leafSize(c);
        } else {
            words[link] = record;
            words[link + 1] = 0;
        }
    }

    private void empty(int id, int side) {
        int base = STRIDE * id, box = base + (side == 0 ? LEFT : RIGHT), link = base + LINKS + 2 * side;
        for (int a = 0; a < 3; a++) {
            words[box + a] = Float.floatToRawIntBits(Float.POSITIVE_INFINITY);
            words[box + 3 + a] = Float.floatToRawIntBits(Float.NEGATIVE_INFINITY);
        }
        words[link] = 0;
        words[link + 1] = 1;      // a "leaf" no ray reaches: its box is empty
    }

    /** A child's code, from its link at {@code link} of {@code words}: its record's index, or {@code -1 - link} for a leaf. */
    static int code(int[] words, int link) {
        return words[link + 1] > 0 ? -1 - link : words[link];
    }

    /** The first word of the box of the leaf whose link is at {@code link} (a record's left or right link). */
    static int boxOf(int link) {
        return (link & -STRIDE) + 3 * ((link & (STRIDE - 1)) - LINKS);
    }
}
