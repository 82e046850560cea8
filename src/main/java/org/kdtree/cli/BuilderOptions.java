package org.kdtree.cli;

import org.kdtree.build.Builders;
import org.kdtree.build.CyclingAxisBuilder;
import org.kdtree.build.KdTreeBuilder;
import org.kdtree.build.Quality;
import org.kdtree.build.SahBuilder;
import org.kdtree.limits.Limits;
import org.kdtree.tree.CostModel;
import picocli.CommandLine.Option;

/** The builder options every command shares (a picocli mixin). */
public final class BuilderOptions {
    @Option(names = {"-b", "--builder"}, defaultValue = "sah",
            description = "Builder: sah, median-plane, object-median, or a registered name (default: ${DEFAULT-VALUE}).")
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
            description = "At most B references per primitive in the tree, 1..65536 (default 256): "
                    + "where overlapping geometry would need more, nodes become leaves early and the output says so.")
    Integer referenceBudget;

    @Option(names = "--min-prims", description = "Kmintri for the median builders (default 2).")
    Integer minPrims;

    @Option(names = "--quality", description = "SAH preset: ${COMPLETION-CANDIDATES}: fast (depth cap 8 + 0.8 log2 N), "
            + "balanced (8 + 1.0 log2 N), exact (the default tree); --algorithm and --max-depth, if given, override it.")
    Quality quality;

    @Option(names = "--algorithm", description = "SAH plane search: ${COMPLETION-CANDIDATES} (same tree, different time).")
    SahBuilder.Algorithm algorithm;

    @Option(names = "--bins", description = "Bins per axis for --algorithm BINNED (default 32).")
    Integer bins;

    @Option(names = "--exact-below", description = "BINNED: nodes with fewer references use the exact sweep (default 64; 0 = never).")
    Integer exactBelow;

    @Option(names = "--no-perfect-splits", description = "Use bounding boxes instead of exact clipping.")
    boolean noPerfectSplits;

    /**
     * A builder configured from the options; each value is checked against its {@link Limits} entry first.
     *
     * @return a new builder of the chosen kind, with every given option applied
     */
    public KdTreeBuilder create() {
        checkLimits();
        KdTreeBuilder b = Builders.create(builder);
        if (maxDepth != null) b.maxDepth(maxDepth);
        if (kt != null || ki != null) {
            CostModel m = b.costModel();
            b.costModel(new CostModel(kt != null ? kt : m.kt(), ki != null ? ki : m.ki()));
        }
        if (noPerfectSplits) b.perfectSplits(false);
        if (referenceBudget != null) b.referenceBudget(referenceBudget);
        if (b instanceof SahBuilder sah) {
            if (quality != null) sah.quality(quality);
            if (maxDepth != null) sah.maxDepth(maxDepth);
            if (lambda != null) sah.emptyWeight(lambda);
            if (algorithm != null) sah.algorithm(algorithm);
            if (bins != null) sah.bins(bins);
            if (exactBelow != null) sah.exactBelow(exactBelow);
        } else if (lambda != null || algorithm != null || bins != null || exactBelow != null || quality != null) {
            throw new IllegalArgumentException(
                    "--lambda, --algorithm, --quality, --bins and --exact-below apply to the sah builder only");
        }
        if (minPrims != null) {
            if (b instanceof CyclingAxisBuilder c) c.minPrimitives(minPrims);
            else throw new IllegalArgumentException("--min-prims applies to the median builders only");
        }
        return b;
    }

    /** Each given option against its limit, so that the error names the option, not the setter. */
    private void checkLimits() {
        if (lambda != null) Limits.LAMBDA.check("--lambda", lambda);
        if (kt != null) Limits.KT.check("--kt", kt);
        if (ki != null) Limits.KI.check("--ki", ki);
        if (maxDepth != null) Limits.MAX_DEPTH.check("--max-depth", maxDepth);
        if (referenceBudget != null) Limits.REFERENCE_BUDGET.check("--reference-budget", referenceBudget);
        if (minPrims != null) Limits.MIN_PRIMITIVES.check("--min-prims", minPrims);
        if (bins != null) Limits.BINS.check("--bins", bins);
        if (exactBelow != null) Limits.EXACT_BELOW.check("--exact-below", exactBelow);
    }
}
