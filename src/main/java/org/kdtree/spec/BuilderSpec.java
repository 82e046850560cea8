package org.kdtree.spec;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.stream.Collectors;
import org.kdtree.accel.AccelerationStructure;
import org.kdtree.accel.Setting;
import org.kdtree.accel.Settings;
import org.kdtree.accel.StructureBuilder;
import org.kdtree.bvh.BvhBuilder;
import org.kdtree.kdtree.KdTreeBuilder;
import org.kdtree.kdtree.Supervisor;
import org.kdtree.shape.Primitives;

/**
 * What a structure is to be built with: a builder's name (as {@link #names()} knows it) and the
 * {@link Settings} given for it; a row not given keeps its default. The command line fills one
 * from its options, the workbench edits one, the trade-off study and the benchmarks list theirs;
 * {@link #structureBuilder()} makes the builder, so a builder on the class path (found by
 * {@link Builders}) joins all of them.
 *
 * <p>One validation, one rule: each value is checked against its range when given
 * ({@link #with}), and making the builder refuses a row that the builder does not take, with a
 * line naming it, rather than ignoring it. {@link #forBuilder} is the explicit way to carry
 * settings over to another builder.
 *
 * <p>This is the layer that picks a structure by name: the kd-tree builders of {@link Builders}
 * and the bounding volume hierarchy's ({@value BvhBuilder#NAME}). {@link #build} makes either,
 * {@link #create()} the kd-tree builders only.
 */
public final class BuilderSpec {
    private final String builder;
    private final Settings given;

    private BuilderSpec(String builder, Settings given) {
        this.builder = Objects.requireNonNull(builder, "builder");
        this.given = given;
    }

    /**
     * {@return a spec of the builder {@code name} with its default settings}
     *
     * @param name a builder's name, e.g. "sah" (checked when the builder is made)
     */
    public static BuilderSpec of(String name) {
        return new BuilderSpec(name, Settings.DEFAULTS);
    }

    /** {@return the builder's name} */
    public String builder() { return builder; }

    /** {@return the settings given, one value} */
    public Settings settings() { return given; }

    /** {@return every name a spec can take: the kd-tree builders ({@link Builders#names()}), then the BVH's} */
    public static List<String> names() {
        List<String> all = new ArrayList<>(Builders.names());
        all.add(BvhBuilder.NAME);
        return List.copyOf(all);
    }

    /** A new builder of {@code name} with its defaults: a kd-tree builder or the BVH's; an unknown name's line lists every name, bvh too. */
    static StructureBuilder newBuilder(String name) {
        if (name.equals(BvhBuilder.NAME)) return new BvhBuilder();
        if (!Builders.names().contains(name))
            throw new IllegalArgumentException("unknown builder '" + name + "' (known: " + String.join(", ", names()) + ")");
        return Builders.create(name);
    }

    /** The rows the builder {@code name} takes, without making one each time (the registry keeps them). */
    static List<Setting<?>> settingRows(String name) {
        return name.equals(BvhBuilder.NAME) ? BVH_ROWS : Builders.settingRows(name);
    }

    private static final List<Setting<?>> BVH_ROWS = new BvhBuilder().settingRows();

    /**
     * {@return this spec with {@code setting} given as {@code value}, or no longer given if {@code value} is null}
     *
     * @param setting the setting
     * @param value   its value, checked against its limit
     * @param <T>     the value's type
     * @throws Setting.Refused if the value is out of range (naming the setting)
     */
    public <T> BuilderSpec with(Setting<T> setting, T value) {
        return new BuilderSpec(builder, given.with(setting, value));
    }

    /**
     * {@return the value given for {@code setting}, or null}
     *
     * @param setting the setting
     * @param <T>     the value's type
     */
    public <T> T get(Setting<T> setting) {
        return given.given(setting);
    }

    /**
     * {@return the value given for {@code setting}, or else the builder's} (null for a setting the builder does not take)
     *
     * @param setting the setting
     * @param <T>     the value's type
     */
    public <T> T value(Setting<T> setting) {
        T v = get(setting);
        if (v != null) return v;
        return settingRows(builder).contains(setting) ? setting.defaultValue() : null;
    }

    /**
     * {@return the same settings for the builder {@code name}: those that apply to it} (the others are dropped, explicitly)
     *
     * @param name another builder's name
     */
    public BuilderSpec forBuilder(String name) {
        newBuilder(name);   // an unknown name: one line listing every name
        return new BuilderSpec(name, given.only(settingRows(name)));
    }

    /**
     * {@return this spec over {@code base}: with each setting {@code base} gives that applies to
     * this builder and that this spec does not give itself} (a study's common settings under each variant's own)
     *
     * @param base the settings to fill in from (its builder's name is not used)
     */
    public BuilderSpec over(BuilderSpec base) {
        return new BuilderSpec(builder, base.forBuilder(builder).given.with(given));
    }

    /**
     * {@return every row of every builder known by name, once each, the SAH's preset first}: the
     * one table of builder settings, which the command line's options, the workbench's controls
     * and docs/limits.md are made from (a loaded plug-in's rows join it)
     */
    public static List<Setting<?>> allSettingRows() { return SettingsTable.all(); }

    /**
     * {@return the builders {@code row} applies to, as a message says it}: "every builder", "the
     * kd-tree builders", "the sah builder", "the sah and bvh builders"
     * @param row a row of {@link #allSettingRows()}
     */
    public static String ownerName(Setting<?> row) { return SettingsTable.ownerName(row); }

    /**
     * {@return whether some kd-tree builder takes {@code row}} (a command that needs a kd-tree offers only those)
     * @param row a row of {@link #allSettingRows()}
     */
    public static boolean takenByKdTrees(Setting<?> row) { return SettingsTable.takenByKdTrees(row); }

    /**
     * {@return whether every builder known by name takes {@code row}}
     * @param row a row of {@link #allSettingRows()}
     */
    public static boolean appliesToEvery(Setting<?> row) { return SettingsTable.appliesToEvery(row); }

    /**
     * {@return whether the builder {@code name} takes {@code setting}}
     *
     * @param setting the setting
     * @param name    a registered builder's name
     */
    public static boolean applies(Setting<?> setting, String name) {
        return settingRows(name).contains(setting);
    }

    /**
     * A new builder of this spec's name, of either structure, with the given settings.
     *
     * @return the builder
     * @throws IllegalArgumentException if no builder has that name; a {@link Setting.Refused} if
     *         a given setting does not apply to it (the message names every such setting and whom it applies to)
     */
    public StructureBuilder structureBuilder() {
        return applied(newBuilder(builder));
    }

    /**
     * A new kd-tree builder of this spec's name, with the given settings.
     *
     * @return the builder
     * @throws IllegalArgumentException if no builder has that name, if it is the BVH's (which
     *         makes no kd-tree), or if a given setting does not apply to it (the message names
     *         every such setting and whom it applies to)
     */
    public KdTreeBuilder create() {
        if (builder.equals(BvhBuilder.NAME))
            throw new IllegalArgumentException("the " + builder + " builder makes a bounding volume hierarchy, which answers ray queries"
                    + " only (structureBuilder(), build()); a kd-tree needs a kd-tree builder: " + String.join(", ", Builders.names()));
        return applied(Builders.create(builder));
    }

    /**
     * Builds the structure this spec names over {@code prims}: a kd-tree (under {@code supervisor},
     * which watches a builder that is not the library's) or a bounding volume hierarchy.
     *
     * @param prims      the primitives
     * @param supervisor runs a kd-tree builder; null to build on the calling thread, unsupervised
     * @return the structure
     * @throws IllegalArgumentException as {@link #structureBuilder()}
     * @throws org.kdtree.kdtree.BuilderFault if a supervised kd-tree builder failed
     */
    public AccelerationStructure build(Primitives prims, Supervisor supervisor) {
        StructureBuilder b = structureBuilder();
        if (supervisor != null && b instanceof KdTreeBuilder kd) return supervisor.build(kd, prims);
        return b.build(prims);
    }

    /**
     * {@return whether the builder is the library's own} (a kd-tree builder of the library or the
     * course's example, or the BVH's), trusted to return and timed as it is; any other (a
     * student's, a plug-in's) runs under a supervisor
     *
     * @throws IllegalArgumentException as {@link #structureBuilder()}
     */
    public boolean librarys() {
        StructureBuilder b = structureBuilder();
        return !(b instanceof KdTreeBuilder kd) || Supervisor.isLibrarys(kd);
    }

    /** {@return the builder's settings in one line} (its {@code describeSettings}) */
    public String describe() {
        return structureBuilder().describeSettings();
    }

    private <B extends StructureBuilder> B applied(B b) {
        refuseWhatDoesNotApply(b);
        b.configure(given);
        return b;
    }

    private void refuseWhatDoesNotApply(StructureBuilder b) {
        List<Setting<?>> rows = b.settingRows();
        for (Setting<?> s : given.givenRows()) {
            if (rows.contains(s)) continue;
            String owner = SettingsTable.ownerName(s);
            List<Setting<?>> others = given.givenRows().stream().filter(o -> !rows.contains(o) && SettingsTable.ownerName(o).equals(owner))
                    .toList();
            throw new Setting.Refused(others, naming -> others.stream().map(naming).collect(Collectors.joining(", "))
                    + (others.size() > 1 ? " apply" : " applies") + " to " + owner + " only, not to " + builder);
        }
    }

    @Override public boolean equals(Object o) {
        return o instanceof BuilderSpec s && s.builder.equals(builder) && s.given.equals(given);
    }

    @Override public int hashCode() { return builder.hashCode() * 31 + given.hashCode(); }

    /** {@return the spec as options, in the table's order}, e.g. {@code sah --lambda 0.5 --algorithm BINNED} (perfect splits: the option only when off) */
    @Override public String toString() {
        List<Setting<?>> order = new ArrayList<>(SettingsTable.all());
        for (Setting<?> row : given.givenRows()) if (!order.contains(row)) order.add(row);
        Settings ordered = Settings.DEFAULTS;
        for (Setting<?> row : order) ordered = ordered.with(given.only(List.of(row)));
        String options = ordered.toString();
        return options.isEmpty() ? builder : builder + " " + options;
    }
}
