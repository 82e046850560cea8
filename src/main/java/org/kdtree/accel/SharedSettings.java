package org.kdtree.accel;

import org.kdtree.limits.Limits;

/**
 * The setting rows that more than one structure's builders take, declared once, here, below
 * them all: the cost model (Kt, Ki), the depth cap, the threads, the bins of a binned SAH and the
 * largest leaf. Each builder that takes one lists it among its {@link StructureBuilder#settingRows()}.
 */
public final class SharedSettings {
    private SharedSettings() {
    }

    /** Kt, the cost of one traversal step (Wald and Havran's, {@link CostModel#WALD_HAVRAN}, by default). */
    public static final Setting<Double> KT = Setting.real("--kt", Limits.KT, CostModel.WALD_HAVRAN.kt(),
            "cost of traversing one node (the SAH's, and every tree's expected cost)");
    /** Ki, the cost of one primitive test. */
    public static final Setting<Double> KI = Setting.real("--ki", Limits.KI, CostModel.WALD_HAVRAN.ki(),
            "cost of intersecting one primitive (the SAH's, and every tree's expected cost)");
    /** Kmaxdepth, or -1 for the automatic depth cap. */
    public static final Setting<Integer> MAX_DEPTH = Setting.whole("--max-depth", Limits.MAX_DEPTH, -1,
            "the depth cap: no node deeper is split");
    /** Threads building the structure. */
    public static final Setting<Integer> THREADS = Setting.whole("--threads", Limits.THREADS, 1,
            "threads building the tree (the same tree at any count)");
    /** Bins per axis of a binned SAH. */
    public static final Setting<Integer> BINS = Setting.whole("--bins", Limits.BINS, 32,
            "bins per axis of the BINNED plane search and of the bvh builder's SAH");
    /** The largest leaf. */
    public static final Setting<Integer> LEAF_SIZE = Setting.whole("--leaf-size", Limits.LEAF_SIZE, 16,
            "the largest leaf, unless its primitives coincide or the depth cap is reached");

    /**
     * {@return the cost model {@code settings} give}
     *
     * @param settings a builder's settings
     */
    public static CostModel costModel(Settings settings) {
        return new CostModel(settings.get(KT), settings.get(KI));
    }

    /**
     * {@return {@code settings} with Kt and Ki those of {@code model}}
     *
     * @param settings a builder's settings
     * @param model    Kt and Ki, each checked against its range
     */
    public static Settings withCostModel(Settings settings, CostModel model) {
        return settings.with(KT, model.kt()).with(KI, model.ki());
    }
}
