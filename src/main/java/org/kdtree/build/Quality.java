package org.kdtree.build;

/**
 * Named SAH settings along the measured trade-off between build time and tree quality
 * (docs/performance.md, "Quality presets"). On the meshes measured, capping the depth of the
 * exact event build was the cheapest way to give up a little quality: below the cap the SAH
 * tree goes on splitting small nodes that each save little, and they are most of the build.
 * Binned SAH did not buy as much time for the same loss (same document).
 */
public enum Quality {
    /** Depth cap {@code 8 + 0.8 log2 N}: about half the exact build time, within 15 % of its expected cost. */
    FAST(0.8),
    /** Depth cap {@code 8 + 1.0 log2 N}: about two thirds of the exact build time, within 3 % of its expected cost. */
    BALANCED(1.0),
    /** The exact SAH tree (event algorithm) under the default cap {@code 8 + 1.3 log2 N}. */
    EXACT(KdTreeBuilder.DEFAULT_DEPTH_FACTOR);

    private final double depthFactor;

    Quality(double depthFactor) {
        this.depthFactor = depthFactor;
    }

    /** {@return c in this preset's depth cap {@code 8 + c log2 N}} */
    public double depthFactor() { return depthFactor; }

    /**
     * Sets {@code sah}'s algorithm (event) and automatic depth cap to this preset's, clearing an
     * explicit Kmaxdepth (set one after the preset to override it); other settings are left alone.
     * @param sah the builder to set
     * @return {@code sah}
     */
    public SahBuilder applyTo(SahBuilder sah) {
        sah.algorithm(SahBuilder.Algorithm.EVENT).maxDepth(-1);
        sah.depthFactor(depthFactor);
        return sah;
    }
}
