package org.kdtree.tradeoff;

import java.util.ArrayList;
import java.util.List;
import org.kdtree.build.BuilderSpec;
import org.kdtree.build.Builders;
import org.kdtree.build.KdTreeBuilder;
import org.kdtree.build.Quality;
import org.kdtree.build.SahBuilder.Algorithm;
import org.kdtree.build.Setting;

/**
 * One builder configuration of the trade-off study: a short name and its builder specification.
 *
 * @param name how the study's table and chart name it
 * @param spec the builder and its settings
 */
public record Variant(String name, BuilderSpec spec) {

    /** {@return a new builder with this variant's settings} */
    public KdTreeBuilder create() {
        return spec.create();
    }

    /**
     * Every variant the study compares: the two median builders, exact SAH with lambda 1.0, 0.8
     * and 0.5 (and the sorted algorithm, same tree, for its build time), binned SAH with B = 8,
     * 32, 256 (and pure binning without the exact sweep of small nodes), SAH without perfect
     * splits, SAH under depth caps 12, 16 and 20, the quality presets fast (binned, leaves below 11
     * references) and balanced (exact, leaves below 6); then every
     * other registered builder (a student's too) with its default settings.
     *
     * @return the variants, in that order
     */
    public static List<Variant> all() {
        BuilderSpec sah = BuilderSpec.of("sah");
        List<Variant> v = new ArrayList<>();
        v.add(new Variant("median-plane", BuilderSpec.of("median-plane")));
        v.add(new Variant("object-median", BuilderSpec.of("object-median")));
        for (double lambda : new double[] {1.0, 0.8, 0.5})
            v.add(new Variant("sah-exact-l" + lambda, sah.with(Setting.LAMBDA, lambda)));
        v.add(new Variant("sah-sorted-l0.8", sah.with(Setting.ALGORITHM, Algorithm.SORTED)));
        BuilderSpec binned = sah.with(Setting.ALGORITHM, Algorithm.BINNED);
        for (int b : new int[] {8, 32, 256})
            v.add(new Variant("sah-binned-b" + b, binned.with(Setting.BINS, b)));
        v.add(new Variant("sah-binned-b32-pure", binned.with(Setting.BINS, 32).with(Setting.EXACT_BELOW, 0)));
        v.add(new Variant("sah-no-perfect-splits", sah.with(Setting.PERFECT_SPLITS, false)));
        for (int d : new int[] {12, 16, 20})
            v.add(new Variant("sah-maxdepth-" + d, sah.with(Setting.MAX_DEPTH, d)));
        v.add(new Variant("sah-fast", sah.with(Setting.QUALITY, Quality.FAST)));
        v.add(new Variant("sah-balanced", sah.with(Setting.QUALITY, Quality.BALANCED)));
        for (String name : Builders.names())
            if (v.stream().noneMatch(x -> x.spec().builder().equals(name))) v.add(new Variant(name, BuilderSpec.of(name)));
        return v;
    }

    /** {@return a few variants for a quick look (and for tests): median plane, exact SAH, binned B = 8 and 32} */
    public static List<Variant> quick() {
        return all().stream().filter(v -> List.of("median-plane", "sah-exact-l0.8", "sah-binned-b8", "sah-binned-b32")
                .contains(v.name())).toList();
    }
}
