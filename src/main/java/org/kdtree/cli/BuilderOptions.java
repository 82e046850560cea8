package org.kdtree.cli;

import org.kdtree.build.BuilderSpec;
import org.kdtree.build.KdTreeBuilder;
import org.kdtree.build.Quality;
import org.kdtree.build.SahBuilder;
import org.kdtree.build.Setting;
import picocli.CommandLine.Option;

/** The builder options every command shares (a picocli mixin): they fill a {@link BuilderSpec}. */
public final class BuilderOptions {
    @Option(names = {"-b", "--builder"}, defaultValue = "sah",
            description = "Builder: sah, median-plane, object-median, sliding-midpoint, or a registered name (default: ${DEFAULT-VALUE}).")
    String builder;

    @Option(names = "--lambda", description = "SAH empty-voxel weight, 0.01..1 (default 0.8).")
    Double lambda;

    @Option(names = "--kt", description = "Traversal cost Kt, 0..10000 (default 15).")
    Double kt;

    @Option(names = "--ki", description = "Intersection cost Ki, 0.001..10000 (default 20).")
    Double ki;

    @Option(names = "--max-depth", description = "Kmaxdepth, 0..64 (default: 8 + 1.3 log2 N).")
    Integer maxDepth;

    @Option(names = "--reference-budget", paramLabel = "B",
            description = "At most B references per primitive in the tree, 1 to 65536 (default 256): "
                    + "where overlapping geometry would need more, nodes become leaves early and the output says so.")
    Integer referenceBudget;

    @Option(names = "--min-prims", description = "Kmintri for the median builders (default 2).")
    Integer minPrims;

    @Option(names = "--quality", description = "SAH preset: ${COMPLETION-CANDIDATES}: fast (binned, leaves below 11 references), "
            + "balanced (exact search, leaves below 6), exact (the default tree); options given with it override its settings.")
    Quality quality;

    @Option(names = "--algorithm", description = "SAH plane search: ${COMPLETION-CANDIDATES}. NAIVE, SORTED and EVENT build the same tree "
            + "in different times; BINNED builds another (planes at bin boundaries only, see --bins).")
    SahBuilder.Algorithm algorithm;

    @Option(names = "--bins", description = "Bins per axis for --algorithm BINNED (default 32).")
    Integer bins;

    @Option(names = "--exact-below", description = "BINNED: nodes with fewer references use the exact sweep (default 64; 0 = never).")
    Integer exactBelow;

    @Option(names = "--leaf-below", description = "SAH: nodes with fewer references become leaves without a plane search, "
            + "1 to 65536 (default 1: only empty nodes).")
    Integer leafBelow;

    @Option(names = "--no-perfect-splits", description = "Use bounding boxes instead of exact clipping.")
    boolean noPerfectSplits;

    @Option(names = "--leaf-size", description = "Largest leaf of the sliding-midpoint builder, 1 to 65536 (default 16).")
    Integer leafSize;

    /**
     * {@return the builder specification the options give} (each value checked against its limit, the error naming the option)
     */
    public BuilderSpec spec() {
        return BuilderSpec.of(builder)
                .with(Setting.QUALITY, quality)
                .with(Setting.KT, kt)
                .with(Setting.KI, ki)
                .with(Setting.MAX_DEPTH, maxDepth)
                .with(Setting.REFERENCE_BUDGET, referenceBudget)
                .with(Setting.PERFECT_SPLITS, noPerfectSplits ? Boolean.FALSE : null)
                .with(Setting.LAMBDA, lambda)
                .with(Setting.ALGORITHM, algorithm)
                .with(Setting.BINS, bins)
                .with(Setting.EXACT_BELOW, exactBelow)
                .with(Setting.LEAF_BELOW, leafBelow)
                .with(Setting.MIN_PRIMITIVES, minPrims)
                .with(Setting.LEAF_SIZE, leafSize);
    }

    /**
     * A builder configured from the options.
     *
     * @return a new builder of the chosen kind, with every given option applied
     * @throws IllegalArgumentException for a value out of range or an option that does not apply to the builder
     */
    public KdTreeBuilder create() {
        return spec().create();
    }
}
