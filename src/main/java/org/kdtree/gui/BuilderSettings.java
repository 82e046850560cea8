package org.kdtree.gui;

import org.kdtree.build.Builders;
import org.kdtree.build.KdTreeBuilder;
import org.kdtree.build.CyclingAxisBuilder;
import org.kdtree.build.SahBuilder;
import org.kdtree.tree.CostModel;

/**
 * What the workbench's builder controls say: which builder, and the talk's constants Kt, Ki,
 * lambda (empty-voxel weight), Kmintri and Kmaxdepth. Each builder takes the settings that
 * apply to it and ignores the others.
 *
 * @param builder  a name known to {@link Builders}
 * @param kt       traversal cost Kt
 * @param ki       intersection cost Ki
 * @param lambda   SAH weight of a plane that leaves one side empty, in (0, 1]
 * @param minPrims Kmintri of the median builders
 * @param maxDepth Kmaxdepth, or -1 for the default {@code 8 + 1.3 log2 N}
 * @param algorithm how the SAH searches for its planes (the tree is the same; the build time is not)
 */
public record BuilderSettings(String builder, double kt, double ki, double lambda, int minPrims, int maxDepth,
                              SahBuilder.Algorithm algorithm) {
    /** SAH with Wald and Havran's constants and the library's default plane search. */
    public static final BuilderSettings DEFAULT = new BuilderSettings("sah", 15, 20, 0.8, 2, -1, new SahBuilder().algorithm());

    /**
     * {@return these settings with another builder}
     *
     * @param name the builder's name
     */
    public BuilderSettings withBuilder(String name) { return new BuilderSettings(name, kt, ki, lambda, minPrims, maxDepth, algorithm); }
    /**
     * {@return these settings with another Kt}
     *
     * @param v Kt, the cost of traversing a node
     */
    public BuilderSettings withKt(double v) { return new BuilderSettings(builder, v, ki, lambda, minPrims, maxDepth, algorithm); }
    /**
     * {@return these settings with another Ki}
     *
     * @param v Ki, the cost of intersecting an object
     */
    public BuilderSettings withKi(double v) { return new BuilderSettings(builder, kt, v, lambda, minPrims, maxDepth, algorithm); }
    /**
     * {@return these settings with another lambda}
     *
     * @param v lambda, the weight of a plane that leaves one child empty
     */
    public BuilderSettings withLambda(double v) { return new BuilderSettings(builder, kt, ki, v, minPrims, maxDepth, algorithm); }
    /**
     * {@return these settings with another Kmintri}
     *
     * @param v Kmintri
     */
    public BuilderSettings withMinPrims(int v) { return new BuilderSettings(builder, kt, ki, lambda, v, maxDepth, algorithm); }
    /**
     * {@return these settings with another Kmaxdepth}
     *
     * @param v Kmaxdepth, or -1 for the automatic depth cap
     */
    public BuilderSettings withMaxDepth(int v) { return new BuilderSettings(builder, kt, ki, lambda, minPrims, v, algorithm); }
    /**
     * {@return these settings with another plane-search algorithm}
     *
     * @param a the SAH's algorithm
     */
    public BuilderSettings withAlgorithm(SahBuilder.Algorithm a) { return new BuilderSettings(builder, kt, ki, lambda, minPrims, maxDepth, a); }

    /** {@return a new builder configured with these settings} */
    public KdTreeBuilder create() {
        KdTreeBuilder b = Builders.create(builder);
        b.costModel(new CostModel(kt, ki));
        b.maxDepth(maxDepth);
        if (b instanceof SahBuilder sah) sah.emptyWeight(lambda).algorithm(algorithm);
        if (b instanceof CyclingAxisBuilder c) c.minPrimitives(minPrims);
        return b;
    }

    /**
     * {@return whether lambda applies to the builder of that name} (an SAH builder).
     *
     * @param builder a builder's name
     */
    public static boolean usesLambda(String builder) {
        return Builders.create(builder) instanceof SahBuilder;
    }

    /**
     * {@return whether Kmintri applies to the builder of that name} (the talk's basic, axis-cycling builders).
     *
     * @param builder a builder's name
     */
    public static boolean usesMinPrims(String builder) {
        return Builders.create(builder) instanceof CyclingAxisBuilder;
    }
}
