package org.kdtree.build;

import java.util.Deque;
import java.util.concurrent.ForkJoinTask;
import org.kdtree.tree.KdTreeWriter;

/**
 * What the SAH's engines share for a parallel build: the right child of a split handed to
 * another thread. It is copied into an idle engine of the same build (with its scratch memory
 * and writer, reused from fork to fork; a new one only when none is idle) and built there while
 * this thread builds the left child; its subtree is then spliced in after the left one, so the
 * tree is the one a single thread writes, in the same order.
 *
 * @param <E> the engine type
 */
abstract class ForkingEngine<E extends ForkingEngine<E>> {
    private final Deque<E> spares;
    /** The writer of the subtree this engine builds when forked. */
    private final KdTreeWriter forkOut;

    ForkingEngine(Deque<E> spares, int dimension) {
        this.spares = spares;
        this.forkOut = new KdTreeWriter(dimension);
    }

    /**
     * Nodes and leaf references an SAH tree has per primitive, a little above what the meshes
     * measured gave (bunny 8.9 and 5.3, its 4 x 4 grid 9.5 and 5.6).
     */
    private static final int NODES_PER_PRIMITIVE = 10, REFS_PER_PRIMITIVE = 6;

    /** Sizes {@code out} up front for the tree of {@code primitives} primitives, rather than growing it by doubling. */
    static void reserve(KdTreeWriter out, long primitives) {
        out.reserve((int) Math.min(1 << 26, NODES_PER_PRIMITIVE * primitives), (int) Math.min(1 << 28, REFS_PER_PRIMITIVE * primitives));
    }

    /** recConst for child c of level d. */
    abstract void recConst(int d, int c, KdTreeWriter out);

    /** A new idle engine of the same build, sharing its list of spares. */
    abstract E newSpare(Deque<E> spares);

    /** Copies the right child of level d into the same place of {@code other}; returns its primitive count. */
    abstract int copyRightChild(int d, E other);

    /** Builds both children of level d, the right one on another thread, after the interior node {@code interior}. */
    final void forkRight(int d, int interior, KdTreeWriter out) {
        E spare = spares.poll();
        E other = spare != null ? spare : newSpare(spares);
        int n = copyRightChild(d, other);
        KdTreeWriter rightOut = ((ForkingEngine<E>) other).forkOut;
        ForkJoinTask<?> right = ForkJoinTask.adapt(() -> {
            rightOut.clear();
            reserve(rightOut, n);
            other.recConst(d, 1, rightOut);
        }).fork();
        recConst(d, 0, out);
        right.join();
        out.setRightChild(interior);
        out.append(rightOut);
        spares.push(other);
    }
}
