package org.kdtree.build;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.function.BiConsumer;
import java.util.function.Function;
import java.util.stream.Collectors;
import org.kdtree.bvh.BvhBuilder;
import org.kdtree.limits.Limit;
import org.kdtree.limits.Limits;
import org.kdtree.tree.CostModel;

/**
 * One setting a builder takes, declared once: its name, its command-line option, its default,
 * its {@link Limits} entry, a line of help, the builders it applies to, and how it is given to
 * and read from a builder. The rows below are the one table of builder settings: the builders
 * start from these defaults, {@link BuilderSpec} checks and applies them, and the command line's
 * options, the workbench's controls and the table in docs/limits.md are made from them.
 *
 * <p>A row names the kd-tree builders it applies to, and, when the bounding volume hierarchy's
 * builder ({@link BvhBuilder}) takes it too, how it is given to that one ({@code andBvh}).
 *
 * <p>Adding a setting is one row here (with the builder's own getter and setter that the row
 * names): the row's declaration adds it to {@link #ALL}, and with it to every command that
 * builds a tree, to the workbench and, once regenerated, to docs/limits.md.
 *
 * @param <T> the value's type
 */
public final class Setting<T> {
    /** The rows, in the order they are declared: each constructor call appends its own. */
    private static final List<Setting<?>> TABLE = new ArrayList<>();

    private static final Owner<KdTreeBuilder> EVERY = new Owner<>(KdTreeBuilder.class, "the kd-tree builders");
    private static final Owner<BvhBuilder> BVH = new Owner<>(BvhBuilder.class, "the bvh builder");
    private static final Owner<SahBuilder> SAH = new Owner<>(SahBuilder.class, "the sah builder");
    private static final Owner<CyclingAxisBuilder> MEDIAN = new Owner<>(CyclingAxisBuilder.class, "the median builders");
    private static final Owner<SlidingMidpointBuilder> SLIDING = new Owner<>(SlidingMidpointBuilder.class, "the sliding-midpoint builder");

    /** A named SAH preset (plane search and leaf size); first in the table, so that the other settings override it. */
    public static final Setting<Quality> QUALITY = new Setting<>("quality", "--quality", Quality.class, null, null, SAH,
            "a named SAH preset, " + Arrays.stream(Quality.values())
                    .map(q -> q.name().toLowerCase(Locale.ROOT) + " (" + q.describe() + ")")
                    .collect(Collectors.joining(", ")) + "; the other settings, if given, override it",
            SahBuilder::quality, b -> null);
    /** Kt, the cost of one traversal step (Wald and Havran's, {@link CostModel#WALD_HAVRAN}, by default). */
    public static final Setting<Double> KT = new Setting<>("--kt", Limits.KT, CostModel.WALD_HAVRAN.kt(), EVERY,
            "cost of traversing one node (the SAH's, and every tree's expected cost)",
            (b, v) -> b.costModel(new CostModel(v, b.costModel().ki())), b -> b.costModel().kt())
            .andBvh("every builder", (h, v) -> h.costModel(new CostModel(v, h.costModel().ki())), h -> h.costModel().kt());
    /** Ki, the cost of one primitive test. */
    public static final Setting<Double> KI = new Setting<>("--ki", Limits.KI, CostModel.WALD_HAVRAN.ki(), EVERY,
            "cost of intersecting one primitive (the SAH's, and every tree's expected cost)",
            (b, v) -> b.costModel(new CostModel(b.costModel().kt(), v)), b -> b.costModel().ki())
            .andBvh("every builder", (h, v) -> h.costModel(new CostModel(h.costModel().kt(), v)), h -> h.costModel().ki());
    /** Kmaxdepth, or -1 for the automatic depth cap. */
    public static final Setting<Integer> MAX_DEPTH = new Setting<>("--max-depth", Limits.MAX_DEPTH, -1, EVERY,
            "the depth cap: no node deeper is split", KdTreeBuilder::maxDepth, KdTreeBuilder::maxDepth)
            .andBvh("every builder", BvhBuilder::maxDepth, BvhBuilder::maxDepth);
    /** B, the references per input primitive the tree may hold. */
    public static final Setting<Integer> REFERENCE_BUDGET = new Setting<>("--reference-budget", Limits.REFERENCE_BUDGET, 256, EVERY,
            "references per primitive the tree may hold: where overlapping geometry would need more, "
                    + "nodes become leaves early and the statistics say so",
            KdTreeBuilder::referenceBudget, KdTreeBuilder::referenceBudget);
    /** Whether straddling primitives are clipped exactly to each child (the option turns it off). */
    public static final Setting<Boolean> PERFECT_SPLITS = new Setting<>("perfect splits", "--no-perfect-splits", Boolean.class, true,
            null, EVERY, "a primitive that straddles a split plane is clipped to each child exactly, not kept whole by its bounding box",
            KdTreeBuilder::perfectSplits, KdTreeBuilder::perfectSplits);
    /** Threads building the tree. */
    public static final Setting<Integer> THREADS = new Setting<>("--threads", Limits.THREADS, 1, EVERY,
            "threads building the tree (the same tree at any count)",
            KdTreeBuilder::threads, KdTreeBuilder::threads)
            .andBvh("every builder", BvhBuilder::threads, BvhBuilder::threads);
    /** lambda, the SAH's weight of a plane that leaves one child empty. */
    public static final Setting<Double> LAMBDA = new Setting<>("--lambda", Limits.LAMBDA, 0.8, SAH,
            "the SAH's weight of a plane that cuts off empty space (1 = no bonus)", SahBuilder::lambda, SahBuilder::lambda);
    /** The SAH's plane search. */
    public static final Setting<SahBuilder.Algorithm> ALGORITHM = new Setting<>("plane search", "--algorithm",
            SahBuilder.Algorithm.class, SahBuilder.Algorithm.EVENT, null, SAH,
            "how the SAH searches for its planes (NAIVE, SORTED and EVENT build the same tree in different times; "
                    + "BINNED builds another, with planes at bin boundaries only)",
            SahBuilder::algorithm, SahBuilder::algorithm);
    /** Bins per axis of the binned SAH (the exact algorithms take it and do not use it) and of the BVH's. */
    public static final Setting<Integer> BINS = new Setting<>("--bins", Limits.BINS, 32, SAH,
            "bins per axis of the BINNED plane search and of the bvh builder's SAH", SahBuilder::bins, SahBuilder::bins)
            .andBvh("the sah and bvh builders", BvhBuilder::bins, BvhBuilder::bins);
    /** The node size below which the binned SAH searches exactly. */
    public static final Setting<Integer> EXACT_BELOW = new Setting<>("--exact-below", Limits.EXACT_BELOW, 64, SAH,
            "the BINNED plane search sweeps nodes of fewer references exactly", SahBuilder::exactBelow, SahBuilder::exactBelow);
    /** The SAH's smallest node it searches a plane for. */
    public static final Setting<Integer> LEAF_BELOW = new Setting<>("--leaf-below", Limits.LEAF_BELOW, 1, SAH,
            "nodes of fewer references become leaves without a plane search (1 = only empty ones)",
            SahBuilder::leafBelow, SahBuilder::leafBelow);
    /** Kmintri, the median builders' smallest node worth splitting. */
    public static final Setting<Integer> MIN_PRIMITIVES = new Setting<>("--min-prims", Limits.MIN_PRIMITIVES, 2, MEDIAN,
            "a voxel with at most this many primitives becomes a leaf", CyclingAxisBuilder::minPrimitives,
            CyclingAxisBuilder::minPrimitives);
    /** The sliding-midpoint builder's largest leaf. */
    public static final Setting<Integer> LEAF_SIZE = new Setting<>("--leaf-size", Limits.LEAF_SIZE, 16, SLIDING,
            "the largest leaf, unless its primitives coincide or the depth cap is reached",
            SlidingMidpointBuilder::leafSize, SlidingMidpointBuilder::leafSize)
            .andBvh("the sliding-midpoint and bvh builders", BvhBuilder::leafSize, BvhBuilder::leafSize);
    /** Children per node of the BVH's wide layout, the one rays traverse. */
    public static final Setting<Integer> BVH_WIDTH = new Setting<>("--bvh-width", Limits.BVH_WIDTH, 4, BVH,
            "children per node of the collapsed layout that rays traverse (the binary tree is built first)",
            BvhBuilder::width, BvhBuilder::width);

    /** Every setting, in the order a spec applies them (the preset first, so that what follows overrides it). */
    public static final List<Setting<?>> ALL = List.copyOf(TABLE);

    /** The builders a setting applies to: a class and its subclasses, and how a message names them. */
    private record Owner<B>(Class<B> type, String name) {
    }

    private final String name;
    private final String option;
    private final Class<T> type;
    private final T defaultValue;
    private final Limit limit;
    private final Owner<?> owner;
    private final String help;
    private final BiConsumer<Object, T> give;
    private final Function<Object, T> read;
    /** How the BVH's builder takes it, when it does (else null); and the name of all the builders that take it. */
    private BiConsumer<BvhBuilder, T> giveBvh;
    private Function<BvhBuilder, T> readBvh;
    private String ownerName;

    /** A number in the range of {@code limit}, named by the limit's title. */
    @SuppressWarnings("unchecked")
    private <B> Setting(String option, Limit limit, T defaultValue, Owner<B> owner, String help,
                                              BiConsumer<B, T> give, Function<B, T> read) {
        this(limit.title(), option, (Class<T>) defaultValue.getClass(), defaultValue, limit, owner, help, give, read);
    }

    @SuppressWarnings("unchecked")
    private <B> Setting(String name, String option, Class<T> type, T defaultValue, Limit limit,
                                              Owner<B> owner, String help, BiConsumer<B, T> give, Function<B, T> read) {
        this.name = name;
        this.option = option;
        this.type = type;
        this.defaultValue = defaultValue;
        this.limit = limit;
        this.owner = owner;
        this.help = help;
        this.give = (b, v) -> give.accept((B) b, v);
        this.read = b -> read.apply((B) b);
        this.ownerName = owner.name();
        if (limit != null) check(defaultValue);
        TABLE.add(this);
    }

    /** The BVH's builder takes this kd-tree setting too, as {@code give} and {@code read} say; {@code owners} names all who take it. */
    private Setting<T> andBvh(String owners, BiConsumer<BvhBuilder, T> give, Function<BvhBuilder, T> read) {
        this.giveBvh = give;
        this.readBvh = read;
        this.ownerName = owners;
        return this;
    }

    /** {@return what the setting is called, in the talk's words where it has one}, e.g. "lambda", "Kmaxdepth" */
    public String name() { return name; }

    /** {@return the command-line option that gives it}, e.g. {@code --lambda}; errors name the setting by it */
    public String option() { return option; }

    /** {@return the type of its value}: Double, Integer, Boolean or an enum */
    public Class<T> type() { return type; }

    /**
     * {@return the value the library's builders start from}, null for a preset (none is applied
     * unless given). A boolean setting's option switches it away from this default.
     */
    public T defaultValue() { return defaultValue; }

    /** {@return its allowed range}, null for a setting that is not a number */
    public Limit limit() { return limit; }

    /** {@return one line on what it does}, without its range, default or builders (each reader adds those its own way) */
    public String help() { return help; }

    /** {@return the builders it applies to, as a message says it}, e.g. "the sah builder", "every builder" */
    public String ownerName() { return ownerName; }

    /** {@return whether only the BVH's builder takes it (no kd-tree builder does)} */
    public boolean bvhOnly() { return owner == BVH; }

    /** {@return whether every builder takes it, the BVH's too} */
    public boolean appliesToEvery() { return owner == EVERY && giveBvh != null; }

    /**
     * {@return whether {@code builder} takes this setting} (a builder of the owning class or a
     * subclass of it, or the BVH's builder when the row says so).
     *
     * @param builder a {@link KdTreeBuilder} or a {@link BvhBuilder}
     */
    public boolean appliesTo(Object builder) {
        return owner.type().isInstance(builder) || giveBvh != null && builder instanceof BvhBuilder;
    }

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
    void give(Object builder, Object value) {
        if (giveBvh != null && builder instanceof BvhBuilder h) giveBvh.accept(h, type.cast(value));
        else give.accept(builder, type.cast(value));
    }

    /**
     * {@return the value {@code builder} has}, null for a preset (which is not a value a builder keeps).
     *
     * @param builder a builder this setting applies to
     */
    public T read(Object builder) {
        if (readBvh != null && builder instanceof BvhBuilder h) return readBvh.apply(h);
        return read.apply(builder);
    }

    /**
     * {@return {@code value} as people write it}: whole numbers without a decimal point, on/off for a switch, an enum's name
     *
     * @param value a value of this setting, or null
     */
    public String format(Object value) {
        if (value == null) return "none";
        if (value instanceof Boolean on) return on ? "on" : "off";
        if (value instanceof Number n) return Limit.format(n.doubleValue());
        return value.toString();
    }

    @Override public String toString() { return option; }
}
