package org.kdtree.build;

import java.util.List;
import java.util.function.BiConsumer;
import java.util.function.Function;
import org.kdtree.limits.Limit;
import org.kdtree.limits.Limits;
import org.kdtree.tree.CostModel;

/**
 * One setting a builder takes, as a {@link BuilderSpec} names it: its command-line option, its
 * {@link Limits} entry, the builders it applies to, and how it is given to and read from a
 * builder. The list {@link #ALL} is the one place that says which settings exist; the command
 * line, the workbench, the trade-off study and the benchmarks all go through it.
 *
 * @param <T> the value's type
 */
public final class Setting<T> {
    /** A named SAH preset: the event algorithm under a depth cap; applied first, so that the other settings override it. */
    public static final Setting<Quality> QUALITY = sah("--quality", Quality.class, null,
            SahBuilder::quality, b -> null);
    /** Kt, the cost of one traversal step. */
    public static final Setting<Double> KT = every("--kt", Double.class, Limits.KT,
            (b, v) -> b.costModel(new CostModel(v, b.costModel().ki())), b -> b.costModel().kt());
    /** Ki, the cost of one primitive test. */
    public static final Setting<Double> KI = every("--ki", Double.class, Limits.KI,
            (b, v) -> b.costModel(new CostModel(b.costModel().kt(), v)), b -> b.costModel().ki());
    /** Kmaxdepth, or -1 for the automatic depth cap. */
    public static final Setting<Integer> MAX_DEPTH = every("--max-depth", Integer.class, Limits.MAX_DEPTH,
            KdTreeBuilder::maxDepth, KdTreeBuilder::maxDepth);
    /** B, the references per input primitive the tree may hold. */
    public static final Setting<Integer> REFERENCE_BUDGET = every("--reference-budget", Integer.class, Limits.REFERENCE_BUDGET,
            KdTreeBuilder::referenceBudget, KdTreeBuilder::referenceBudget);
    /** Whether straddling primitives are clipped exactly to each child (the option turns it off). */
    public static final Setting<Boolean> PERFECT_SPLITS = every("--no-perfect-splits", Boolean.class, null,
            KdTreeBuilder::perfectSplits, KdTreeBuilder::perfectSplits);
    /** Threads building the tree. */
    public static final Setting<Integer> THREADS = every("--threads", Integer.class, Limits.THREADS,
            KdTreeBuilder::threads, KdTreeBuilder::threads);
    /** lambda, the SAH's weight of a plane that leaves one child empty. */
    public static final Setting<Double> LAMBDA = sah("--lambda", Double.class, Limits.LAMBDA,
            SahBuilder::emptyWeight, SahBuilder::emptyWeight);
    /** The SAH's plane search. */
    public static final Setting<SahBuilder.Algorithm> ALGORITHM = sah("--algorithm", SahBuilder.Algorithm.class, null,
            SahBuilder::algorithm, SahBuilder::algorithm);
    /** Bins per axis of the binned SAH (the exact algorithms take it and do not use it). */
    public static final Setting<Integer> BINS = sah("--bins", Integer.class, Limits.BINS, SahBuilder::bins, SahBuilder::bins);
    /** The node size below which the binned SAH searches exactly. */
    public static final Setting<Integer> EXACT_BELOW = sah("--exact-below", Integer.class, Limits.EXACT_BELOW,
            SahBuilder::exactBelow, SahBuilder::exactBelow);
    /** The SAH's smallest node it searches a plane for. */
    public static final Setting<Integer> LEAF_BELOW = sah("--leaf-below", Integer.class, Limits.LEAF_BELOW,
            SahBuilder::leafBelow, SahBuilder::leafBelow);
    /** Kmintri, the median builders' smallest node worth splitting. */
    public static final Setting<Integer> MIN_PRIMITIVES = new Setting<>("--min-prims", Integer.class, Limits.MIN_PRIMITIVES,
            CyclingAxisBuilder.class, "the median builders", CyclingAxisBuilder::minPrimitives, CyclingAxisBuilder::minPrimitives);
    /** The sliding-midpoint builder's largest leaf. */
    public static final Setting<Integer> LEAF_SIZE = new Setting<>("--leaf-size", Integer.class, Limits.LEAF_SIZE,
            SlidingMidpointBuilder.class, "the sliding-midpoint builder", SlidingMidpointBuilder::leafSize,
            SlidingMidpointBuilder::leafSize);

    /** Every setting, in the order a spec applies them (a preset first, so that what follows overrides it). */
    public static final List<Setting<?>> ALL = List.of(QUALITY, KT, KI, MAX_DEPTH, REFERENCE_BUDGET, PERFECT_SPLITS, THREADS,
            LAMBDA, ALGORITHM, BINS, EXACT_BELOW, LEAF_BELOW, MIN_PRIMITIVES, LEAF_SIZE);

    private final String option;
    private final Class<T> type;
    private final Limit limit;
    private final Class<? extends KdTreeBuilder> owner;
    private final String ownerName;
    private final BiConsumer<KdTreeBuilder, T> give;
    private final Function<KdTreeBuilder, T> read;

    @SuppressWarnings("unchecked")
    private <B extends KdTreeBuilder> Setting(String option, Class<T> type, Limit limit, Class<B> owner, String ownerName,
                                              BiConsumer<B, T> give, Function<B, T> read) {
        this.option = option;
        this.type = type;
        this.limit = limit;
        this.owner = owner;
        this.ownerName = ownerName;
        this.give = (b, v) -> give.accept((B) b, v);
        this.read = b -> read.apply((B) b);
    }

    private static <T> Setting<T> every(String option, Class<T> type, Limit limit, BiConsumer<KdTreeBuilder, T> give,
                                        Function<KdTreeBuilder, T> read) {
        return new Setting<>(option, type, limit, KdTreeBuilder.class, "every builder", give, read);
    }

    private static <T> Setting<T> sah(String option, Class<T> type, Limit limit, BiConsumer<SahBuilder, T> give,
                                      Function<SahBuilder, T> read) {
        return new Setting<>(option, type, limit, SahBuilder.class, "the sah builder", give, read);
    }

    /** {@return the command-line option that gives it}, e.g. {@code --lambda}; errors name the setting by it. */
    public String option() { return option; }

    /** {@return the type of its value} */
    public Class<T> type() { return type; }

    /** {@return the builders it applies to, as a message says it}, e.g. "the sah builder" */
    public String ownerName() { return ownerName; }

    /**
     * {@return whether {@code builder} takes this setting} (a builder of the owning class or a subclass of it).
     *
     * @param builder a builder
     */
    public boolean appliesTo(KdTreeBuilder builder) { return owner.isInstance(builder); }

    /**
     * {@code value}, checked against this setting's {@link Limits} entry (the error names {@link #option()}).
     *
     * @param value the value, not null
     * @return {@code value}
     * @throws IllegalArgumentException if it is out of range
     */
    T check(T value) {
        if (limit != null) limit.check(option, ((Number) value).doubleValue());
        return type.cast(value);
    }

    /** Gives {@code value} to {@code builder}, which this setting applies to. */
    void give(KdTreeBuilder builder, Object value) { give.accept(builder, type.cast(value)); }

    /**
     * {@return the value {@code builder} has}, null for a preset (which is not a value a builder keeps).
     *
     * @param builder a builder this setting applies to
     */
    public T read(KdTreeBuilder builder) { return read.apply(builder); }

    @Override public String toString() { return option; }
}
