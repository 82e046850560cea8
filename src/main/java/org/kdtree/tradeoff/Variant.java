package org.kdtree.tradeoff;

import java.util.ArrayList;
import java.util.List;
import org.kdtree.accel.SharedSettings;
import org.kdtree.bvh.BvhBuilder;
import org.kdtree.kdtree.KdTreeBuilder;
import org.kdtree.kdtree.Quality;
import org.kdtree.kdtree.SahBuilder.Algorithm;
import org.kdtree.kdtree.SahSettings;
import org.kdtree.spec.BuilderSpec;
import org.kdtree.spec.Builders;

/**
 * One builder configuration of the trade-off study: a short name and its builder specification,
 * of a kd-tree or of a bounding volume hierarchy (whose names start with "bvh").
 *
 * @param name how the study's table and chart name it
 * @param spec the builder and its settings
 */
public record Variant(String name, BuilderSpec spec) {

    /**
     * Every variant the study compares: the two median builders, exact SAH with lambda 1.0, 0.8
     * and 0.5 (and the sorted algorithm, same tree, for its build time), binned SAH with B = 8,
     * 32, 256 (and pure binning without the exact sweep of small nodes), SAH without perfect
     * splits, SAH under depth caps 12, 16 and 20, exact SAH with a lookahead of 1, 2 and 3, the quality presets fast (exact, leaves below 11
     * references) and balanced (exact, leaves below 6); then every
     * other registered builder (a student's too) with its default settings; then the bounding
     * volume hierarchy: by default (4 children per node, 32 bins, leaves up to 16), collapsed to 2
     * and to 8 children (the same binary tree, traced in another layout), with 8 bins (a cheaper,
     * coarser build) and with leaves of one primitive (the deepest tree).
     *
     * @return the variants, in that order
     */
    public static List<Variant> all() {
        BuilderSpec sah = BuilderSpec.of("sah");
        List<Variant> v = new ArrayList<>();
        v.add(new Variant("median-plane", BuilderSpec.of("median-plane")));
        v.add(new Variant("object-median", BuilderSpec.of("object-median")));
        for (double lambda : new double[] {1.0, 0.8, 0.5})
            v.add(new Variant("sah-exact-l" + lambda, sah.with(SahSettings.LAMBDA, lambda)));
        v.add(new Variant("sah-sorted-l0.8", sah.with(SahSettings.ALGORITHM, Algorithm.SORTED)));
        BuilderSpec binned = sah.with(SahSettings.ALGORITHM, Algorithm.BINNED);
        for (int b : new int[] {8, 32, 256})
            v.add(new Variant("sah-binned-b" + b, binned.with(SharedSettings.BINS, b)));
        v.add(new Variant("sah-binned-b32-pure", binned.with(SharedSettings.BINS, 32).with(SahSettings.EXACT_BELOW, 0)));
        v.add(new Variant("sah-no-perfect-splits", sah.with(KdTreeBuilder.PERFECT_SPLITS, false)));
        for (int d : new int[] {12, 16, 20})
            v.add(new Variant("sah-maxdepth-" + d, sah.with(SharedSettings.MAX_DEPTH, d)));
        for (int n : new int[] {1, 2, 3})
            v.add(new Variant("sah-lookahead-" + n, sah.with(SahSettings.LOOKAHEAD, n)));
        v.add(new Variant("sah-fast", sah.with(SahSettings.QUALITY, Quality.FAST)));
        v.add(new Variant("sah-balanced", sah.with(SahSettings.QUALITY, Quality.BALANCED)));
        for (String name : Builders.names())
            if (v.stream().noneMatch(x -> x.spec().builder().equals(name))) v.add(new Variant(name, BuilderSpec.of(name)));
        v.addAll(bvh());
        return v;
    }

    /** The bounding volume hierarchy's variants: its own trade-offs of layout, bins and leaf size. */
    private static List<Variant> bvh() {
        BuilderSpec bvh = BuilderSpec.of(BvhBuilder.NAME);
        return List.of(new Variant("bvh", bvh),
                new Variant("bvh-width2", bvh.with(BvhBuilder.WIDTH, 2)),
                new Variant("bvh-width8", bvh.with(BvhBuilder.WIDTH, 8)),
                new Variant("bvh-b8", bvh.with(SharedSettings.BINS, 8)),
                new Variant("bvh-leaf1", bvh.with(SharedSettings.LEAF_SIZE, 1)));
    }

    /** {@return a few variants for a quick look (and for tests): median plane, exact SAH, binned B = 8 and 32, the BVH} */
    public static List<Variant> quick() {
        return all().stream().filter(v -> List.of("median-plane", "sah-exact-l0.8", "sah-binned-b8", "sah-binned-b32", "bvh")
                .contains(v.name())).toList();
    }
}
