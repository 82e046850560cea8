package org.kdtree.spec;

import java.util.function.Function;
import org.kdtree.accel.AccelerationStructure;
import org.kdtree.bvh.Bvh;
import org.kdtree.kdtree.KdTree;

/**
 * Which of the two structures a built one is, asked in this one place of the picking layer for
 * the one caller that must handle each one's own arrays: a saved tree's writer
 * ({@code treefile.TreeFile}), which writes a kd-tree's nodes and a hierarchy's boxes.
 */
public final class Structures {
    private Structures() {
    }

    /**
     * {@return what {@code kdTree} or {@code bvh} makes of {@code structure}, whichever it is}
     *
     * @param structure a structure that {@link BuilderSpec#build} made
     * @param kdTree    what to do with a kd-tree
     * @param bvh       what to do with a bounding volume hierarchy
     * @param <R>       the answer's type
     * @throws IllegalArgumentException for a structure of another kind
     */
    public static <R> R match(AccelerationStructure structure, Function<KdTree, R> kdTree, Function<Bvh, R> bvh) {
        if (structure instanceof KdTree kd) return kdTree.apply(kd);
        if (structure instanceof Bvh h) return bvh.apply(h);
        throw new IllegalArgumentException("a structure of kind " + structure.kind() + " is neither a kd-tree nor a bounding volume hierarchy");
    }
}
