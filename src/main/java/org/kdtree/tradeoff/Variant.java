package org.kdtree.tradeoff;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Supplier;
import org.kdtree.build.KdTreeBuilder;
import org.kdtree.build.MedianPlaneBuilder;
import org.kdtree.build.ObjectMedianBuilder;
import org.kdtree.build.Quality;
import org.kdtree.build.SahBuilder;
import org.kdtree.build.SahBuilder.Algorithm;

/** One builder configuration of the trade-off study: a short name and a factory. */
public record Variant(String name, Supplier<KdTreeBuilder> factory) {

    /** {@return a new builder with this variant's settings} */
    public KdTreeBuilder create() {
        return factory.get();
    }

    /**
     * Every variant the study compares: the two median builders, exact SAH with lambda 1.0, 0.8
     * and 0.5 (and the sorted algorithm, same tree, for its build time), binned SAH with B = 8,
     * 32, 256 (and pure binning without the exact sweep of small nodes), SAH without perfect
     * splits, SAH under depth caps 12, 16 and 20, and the quality presets fast and balanced.
     *
     * @return the variants, in that order
     */
    public static List<Variant> all() {
        List<Variant> v = new ArrayList<>();
        v.add(new Variant("median-plane", MedianPlaneBuilder::new));
        v.add(new Variant("object-median", ObjectMedianBuilder::new));
        for (double lambda : new double[] {1.0, 0.8, 0.5})
            v.add(new Variant("sah-exact-l" + lambda, () -> new SahBuilder().emptyWeight(lambda)));
        v.add(new Variant("sah-sorted-l0.8", () -> new SahBuilder().algorithm(Algorithm.SORTED)));
        for (int b : new int[] {8, 32, 256})
            v.add(new Variant("sah-binned-b" + b, () -> new SahBuilder().algorithm(Algorithm.BINNED).bins(b)));
        v.add(new Variant("sah-binned-b32-pure", () -> new SahBuilder().algorithm(Algorithm.BINNED).bins(32).exactBelow(0)));
        v.add(new Variant("sah-no-perfect-splits", () -> new SahBuilder().perfectSplits(false)));
        for (int d : new int[] {12, 16, 20})
            v.add(new Variant("sah-maxdepth-" + d, () -> new SahBuilder().maxDepth(d)));
        v.add(new Variant("sah-fast", () -> new SahBuilder().quality(Quality.FAST)));
        v.add(new Variant("sah-balanced", () -> new SahBuilder().quality(Quality.BALANCED)));
        return v;
    }

    /** {@return a few variants for a quick look (and for tests): median plane, exact SAH, binned B = 8 and 32} */
    public static List<Variant> quick() {
        return all().stream().filter(v -> List.of("median-plane", "sah-exact-l0.8", "sah-binned-b8", "sah-binned-b32")
                .contains(v.name())).toList();
    }
}
