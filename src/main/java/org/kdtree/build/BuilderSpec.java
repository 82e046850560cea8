package org.kdtree.build;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Objects;
import java.util.stream.Collectors;
import org.kdtree.bvh.BvhBuilder;
import org.kdtree.shape.Primitives;
import org.kdtree.traverse.AccelerationStructure;

/**
 * What a tree is to be built with: a builder's name (as {@link Builders} knows it) and the
 * {@link Setting}s given for it; a setting not given keeps the builder's default. The command
 * line fills one from its options, the workbench edits one, the trade-off study and the
 * benchmarks list theirs; {@link #create()} makes the builder, so a builder on the class path
 * (found by {@link Builders}) joins all of them.
 *
 * <p>One validation, one rule: each value is checked against its {@link org.kdtree.limits.Limits}
 * entry when given ({@link #with}), and {@link #create()} refuses a setting that does not apply
 * to the builder, with a line naming it, rather than ignoring it.
 * {@link #forBuilder} is the explicit way to carry settings over to another builder.
 *
 * <p>The name {@value BvhBuilder#NAME} is the bounding volume hierarchy's builder
 * ({@link BvhBuilder}), with its rows of the same table: {@link #build} makes either structure,
 * {@link #create()} the kd-tree builders only.
 */
public final class BuilderSpec {
    private final String builder;
    private final Map<Setting<?>, Object> given;

    private BuilderSpec(String builder, Map<Setting<?>, Object> given) {
        this.builder = Objects.requireNonNull(builder, "builder");
        this.given = given;
    }

    /**
     * {@return a spec of the builder {@code name} with its default settings}
     *
     * @param name a builder's name, e.g. "sah" (checked by {@link #create()})
     */
    public static BuilderSpec of(String name) {
        return new BuilderSpec(name, Map.of());
    }

    /** {@return the builder's name} */
    public String builder() { return builder; }

    /** {@return whether it builds a bounding volume hierarchy rather than a kd-tree} */
    public boolean buildsBvh() { return builder.equals(BvhBuilder.NAME); }

    /** {@return every name a spec can take: the kd-tree builders ({@link Builders#names()}), then the BVH's} */
    public static List<String> names() {
        List<String> all = new ArrayList<>(Builders.names());
        all.add(BvhBuilder.NAME);
        return List.copyOf(all);
    }

    /** A new builder of {@code name} with its defaults: a {@link KdTreeBuilder} or a {@link BvhBuilder}. */
    private static Object newBuilder(String name) {
        if (name.equals(BvhBuilder.NAME)) return new BvhBuilder();
        if (!Builders.names().contains(name))
            throw new IllegalArgumentException("unknown builder '" + name + "' (known: " + String.join(", ", names()) + ")");
        return Builders.create(name);
    }

    /**
     * {@return this spec with {@code setting} given as {@code value}, or no longer given if {@code value} is null}
     *
     * @param setting the setting
     * @param value   its value, checked against its limit
     * @param <T>     the value's type
     * @throws IllegalArgumentException if the value is out of range (naming {@link Setting#option()})
     */
    public <T> BuilderSpec with(Setting<T> setting, T value) {
        Map<Setting<?>, Object> m = new LinkedHashMap<>(given);
        if (value == null) m.remove(setting);
        else m.put(setting, setting.check(value));
        return new BuilderSpec(builder, Collections.unmodifiableMap(m));
    }

    /**
     * {@return the value given for {@code setting}, or null}
     *
     * @param setting the setting
     * @param <T>     the value's type
     */
    public <T> T get(Setting<T> setting) {
        return setting.type().cast(given.get(setting));
    }

    /**
     * {@return the value given for {@code setting}, or else the builder's default} (null for a setting the builder does not take)
     *
     * @param setting the setting
     * @param <T>     the value's type
     */
    public <T> T value(Setting<T> setting) {
        T v = get(setting);
        if (v != null) return v;
        Object b = newBuilder(builder);
        return setting.appliesTo(b) ? setting.read(b) : null;
    }

    /**
     * {@return the same settings for the builder {@code name}: those that apply to it} (the others are dropped, explicitly)
     *
     * @param name another builder's name
     */
    public BuilderSpec forBuilder(String name) {
        Object b = newBuilder(name);
        Map<Setting<?>, Object> m = new LinkedHashMap<>();
        given.forEach((s, v) -> {
            if (s.appliesTo(b)) m.put(s, v);
        });
        return new BuilderSpec(name, Collections.unmodifiableMap(m));
    }

    /**
     * {@return this spec over {@code base}: with each setting {@code base} gives that applies to
     * this builder and that this spec does not give itself} (a study's common settings under each variant's own)
     *
     * @param base the settings to fill in from (its builder's name is not used)
     */
    public BuilderSpec over(BuilderSpec base) {
        Map<Setting<?>, Object> m = new LinkedHashMap<>(base.forBuilder(builder).given);
        m.putAll(given);
        return new BuilderSpec(builder, Collections.unmodifiableMap(m));
    }

    /**
     * {@return whether the builder {@code name} takes {@code setting}}
     *
     * @param setting the setting
     * @param name    a registered builder's name
     */
    public static boolean applies(Setting<?> setting, String name) {
        return setting.appliesTo(newBuilder(name));
    }

    /**
     * A new kd-tree builder of this spec's name, with every given setting applied (presets first).
     *
     * @return the builder
     * @throws IllegalArgumentException if no builder has that name, if it is the BVH's (which
     *         makes no kd-tree), or if a given setting does not apply to it (the message names
     *         every such setting and whom it applies to)
     */
    public KdTreeBuilder create() {
        if (buildsBvh())
            throw new IllegalArgumentException("-b " + builder + " builds a bounding volume hierarchy, which answers ray queries"
                    + " only (raycast, stats, render, tradeoff, the workbench); this needs a kd-tree builder: " + String.join(", ", Builders.names()));
        return applied(Builders.create(builder));
    }

    /**
     * A new BVH builder with every given setting applied.
     *
     * @return the builder
     * @throws IllegalArgumentException if this spec names a kd-tree builder, or a given setting does not apply
     */
    public BvhBuilder createBvh() {
        if (!buildsBvh()) throw new IllegalArgumentException(builder + " builds a kd-tree, not a bounding volume hierarchy");
        return applied(new BvhBuilder());
    }

    /**
     * Builds the structure this spec names over {@code prims}: a kd-tree (under {@code supervisor},
     * which watches a builder that is not the library's) or a bounding volume hierarchy.
     *
     * @param prims      the primitives
     * @param supervisor runs a kd-tree builder; null to build on the calling thread, unsupervised
     * @return the structure
     * @throws IllegalArgumentException as {@link #create()} and {@link #createBvh()}
     * @throws BuilderFault if a supervised kd-tree builder failed
     */
    public AccelerationStructure build(Primitives prims, Supervisor supervisor) {
        if (buildsBvh()) return createBvh().build(prims);
        newBuilder(builder);
        KdTreeBuilder b = create();
        return AccelerationStructure.of(supervisor == null ? b.build(prims) : supervisor.build(b, prims));
    }

    /** {@return the builder's settings in one line} (its {@code describeSettings}) */
    public String describe() {
        newBuilder(builder); // an unknown name: the line lists every name, bvh too
        return buildsBvh() ? createBvh().describeSettings() : create().describeSettings();
    }

    private <B> B applied(B b) {
        refuseWhatDoesNotApply(b);
        for (Setting<?> s : Setting.ALL) {
            Object v = given.get(s);
            if (v != null) s.give(b, v);
        }
        return b;
    }

    private void refuseWhatDoesNotApply(Object b) {
        for (Setting<?> s : Setting.ALL) {
            if (!given.containsKey(s) || s.appliesTo(b)) continue;
            String others = Setting.ALL.stream().filter(o -> o.ownerName().equals(s.ownerName()) && given.containsKey(o))
                    .map(Setting::option).collect(Collectors.joining(", "));
            throw new IllegalArgumentException(others + (others.contains(",") ? " apply" : " applies") + " to "
                    + s.ownerName() + " only, not to " + builder);
        }
    }

    @Override public boolean equals(Object o) {
        return o instanceof BuilderSpec s && s.builder.equals(builder) && s.given.equals(given);
    }

    @Override public int hashCode() { return builder.hashCode() * 31 + given.hashCode(); }

    /** {@return the spec as options}, e.g. {@code sah --lambda 0.5 --algorithm BINNED} (perfect splits: the option only when off) */
    @Override public String toString() {
        StringBuilder sb = new StringBuilder(builder);
        for (Setting<?> s : Setting.ALL) {
            Object v = given.get(s);
            if (v instanceof Boolean on) {
                if (!on) sb.append(' ').append(s.option());
            } else if (v != null) {
                sb.append(' ').append(s.option()).append(' ').append(v);
            }
        }
        return sb.toString();
    }
}
