package org.kdtree.build;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Objects;
import java.util.stream.Collectors;

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
        KdTreeBuilder b = Builders.create(builder);
        return setting.appliesTo(b) ? setting.read(b) : null;
    }

    /**
     * {@return the same settings for the builder {@code name}: those that apply to it} (the others are dropped, explicitly)
     *
     * @param name another builder's name
     */
    public BuilderSpec forBuilder(String name) {
        KdTreeBuilder b = Builders.create(name);
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
        return setting.appliesTo(Builders.create(name));
    }

    /**
     * A new builder of this spec's name, with every given setting applied (presets first).
     *
     * @return the builder
     * @throws IllegalArgumentException if no builder has that name, or a given setting does not
     *         apply to it (the message names every such setting and whom it applies to)
     */
    public KdTreeBuilder create() {
        KdTreeBuilder b = Builders.create(builder);
        refuseWhatDoesNotApply(b);
        for (Setting<?> s : Setting.ALL) {
            Object v = given.get(s);
            if (v != null) s.give(b, v);
        }
        return b;
    }

    private void refuseWhatDoesNotApply(KdTreeBuilder b) {
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
