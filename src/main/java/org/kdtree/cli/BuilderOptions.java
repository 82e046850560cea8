package org.kdtree.cli;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;
import org.kdtree.accel.Setting;
import org.kdtree.accel.SharedSettings;
import org.kdtree.bvh.BvhBuilder;
import org.kdtree.limits.Limit;
import org.kdtree.spec.BuilderSpec;
import org.kdtree.spec.Builders;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Model.OptionSpec;

/**
 * The builder options of every command that builds a tree (a picocli mixin): {@code -b NAME}
 * (a kd-tree builder, or {@code bvh} where ray queries are all the command needs; the others
 * refuse it in one line) and one option per row of {@link Setting}, made from the row (its option, help, range,
 * default and builders), so that a setting added there is an option of every such command.
 * The values are kept as typed and checked when {@link #spec()} makes the {@link BuilderSpec},
 * whose errors name the option in one line.
 *
 * <p>A command declares {@code @Mixin BuilderOptions options = new BuilderOptions("sah")} with
 * its own default builder; picocli's model transformer adds the options to the command.
 */
@Command(modelTransformer = AddedOptions.Transformer.class)
final class BuilderOptions implements AddedOptions {
    private final String defaultBuilder;
    private final String role;
    private boolean kdTreesOnly;
    private String threadsHelp;
    private String builder;
    private final Map<Setting<?>, Object> given = new LinkedHashMap<>();

    /** For picocli, should a command declare the mixin without a value: the default builder is sah. */
    public BuilderOptions() {
        this("sah");
    }

    /**
     * Options whose {@code -b} defaults to {@code defaultBuilder}.
     *
     * @param defaultBuilder the command's builder when {@code -b} is not given
     */
    public BuilderOptions(String defaultBuilder) {
        this(defaultBuilder, null);
    }

    /**
     * Options whose {@code -b} has no default, for a command where it means something else.
     *
     * @param defaultBuilder null, or the builder when {@code -b} is not given
     * @param role           what {@code -b} does in the command, for its help (null: "the builder")
     */
    BuilderOptions(String defaultBuilder, String role) {
        this.defaultBuilder = defaultBuilder;
        this.role = role;
    }

    /**
     * Options of a command that needs a kd-tree ({@code knn}, {@code knn-study}, {@code grade}):
     * its help offers neither {@code bvh} nor the settings only the BVH takes.
     *
     * @param defaultBuilder null, or the builder when {@code -b} is not given
     * @param role           what {@code -b} does in the command, for its help (null: "the builder")
     * @return the options
     */
    static BuilderOptions kdTrees(String defaultBuilder, String role) {
        BuilderOptions o = new BuilderOptions(defaultBuilder, role);
        o.kdTreesOnly = true;
        return o;
    }

    /**
     * What {@code --threads} does in this command, where it does more than build (raycast also traces with them).
     *
     * @param help the help's first part, as {@link Setting#help()}
     * @return these options
     */
    BuilderOptions threadsHelp(String help) {
        this.threadsHelp = help;
        return this;
    }

    /** {@return the builder named by {@code -b}, or the command's default (null if it has none)} */
    public String builder() {
        return builder != null ? builder : defaultBuilder;
    }

    /** {@return whether {@code -b} was given} */
    boolean builderGiven() {
        return builder != null;
    }

    /** {@return the settings given, in the order given} */
    Map<Setting<?>, Object> givenSettings() {
        return java.util.Collections.unmodifiableMap(given);
    }

    /** {@return whether any builder option was given} ({@code -b} or a setting) */
    public boolean given() {
        return builder != null || !given.isEmpty();
    }

    /**
     * {@return the builder specification the options give} (each value checked against its limit, the error naming the option)
     *
     * @throws IllegalArgumentException for a value out of range, or if no builder is named and the command has no default
     */
    public BuilderSpec spec() {
        String name = builder();
        if (name == null) throw new IllegalArgumentException("give a builder: -b NAME");
        return spec(name);
    }

    /**
     * {@return the settings given, for the builder {@code name}} (checked as {@link #spec()} checks them)
     *
     * @param name a builder's name
     */
    public BuilderSpec spec(String name) {
        if (kdTreesOnly && name.equals(BvhBuilder.NAME))
            throw new IllegalArgumentException("-b " + name + " builds a bounding volume hierarchy, which answers ray queries only (raycast, "
                    + "stats, render, tradeoff, the workbench); this needs a kd-tree builder: " + String.join(", ", Builders.names()));
        BuilderSpec s = BuilderSpec.of(name);
        for (Map.Entry<Setting<?>, Object> e : given.entrySet()) s = with(s, e.getKey(), e.getValue());
        return s;
    }

    private static <T> BuilderSpec with(BuilderSpec s, Setting<T> setting, Object value) {
        return s.with(setting, setting.type().cast(value));
    }

    /**
     * {@return the value given for {@code setting}, or its default}
     *
     * @param setting a setting
     * @param <T>     its type
     */
    public <T> T value(Setting<T> setting) {
        Object v = given.get(setting);
        return v != null ? setting.type().cast(v) : setting.defaultValue();
    }

    /** Adds {@code -b} and one option per setting to the command that mixes these options in. */
    @Override public void addTo(CommandSpec command) {
        String which = kdTreesOnly ? "Builder: sah, median-plane, object-median, sliding-midpoint or a registered name "
                + "(a kd-tree builder: this command does not take bvh) "
                : "Builder: sah, median-plane, object-median, sliding-midpoint, a registered name, or bvh "
                + "(a bounding volume hierarchy: ray queries and the workbench) ";
        command.addOption(OptionSpec.builder("-b", "--builder").type(String.class).paramLabel("NAME")
                .description(which + (role != null ? "(" + role + ")." : "(default: " + defaultBuilder + ")."))
                .setter(AddedOptions.setter(v -> builder = (String) v)).build());
        for (Setting<?> s : BuilderSpec.allSettingRows())
            if (!kdTreesOnly || BuilderSpec.takenByKdTrees(s)) command.addOption(option(s));
    }

    /** The option of one setting: a switch for a boolean (it turns the default over), else an option with a value. */
    private OptionSpec option(Setting<?> s) {
        boolean flag = s.type() == Boolean.class;
        String help = s == SharedSettings.THREADS && threadsHelp != null ? description(s, threadsHelp) : description(s);
        OptionSpec.Builder b = OptionSpec.builder(s.option()).description(help);
        if (flag) b.type(boolean.class).arity("0");
        else b.type(s.type()).paramLabel(label(s));
        return b.setter(AddedOptions.setter(v -> {
            if (v == null || Boolean.FALSE.equals(v) && flag) given.remove(s);
            else given.put(s, flag ? !(Boolean) s.defaultValue() : v);
        })).build();
    }

    /** "lambda: the SAH's weight of ... (1 = no bonus). 0.01..1, default 0.8; the sah builder only." */
    static String description(Setting<?> s) {
        return description(s, s.help());
    }

    /** The description of {@code s} with {@code help} for its first part. */
    static String description(Setting<?> s, String help) {
        String only = BuilderSpec.appliesToEvery(s) ? "." : "; " + BuilderSpec.ownerName(s) + " only.";
        if (s.type() == Boolean.class)
            return "Turn " + s.name() + " " + s.format(!(Boolean) s.defaultValue()) + " (default " + s.format(s.defaultValue())
                    + "): " + help + only;
        List<String> facts = new ArrayList<>();
        if (s.limit() != null) facts.add(range(s.limit()));
        if (s.type().isEnum()) facts.add("one of " + Arrays.stream(s.type().getEnumConstants()).map(Object::toString)
                .collect(Collectors.joining(", ")));
        facts.add("default " + s.format(s.defaultValue()));
        String f = String.join(", ", facts);
        return s.name() + ": " + help + ". " + Character.toUpperCase(f.charAt(0)) + f.substring(1) + only;
    }

    /** "1 to 256", not 1..256, which picocli may break after the dots. */
    private static String range(Limit l) {
        return Limit.format(l.min()) + " to " + Limit.format(l.max()) + (l.note().isEmpty() ? "" : " (" + l.note() + ")");
    }

    /** The option's value as the usage line shows it: N, a whole number; X, a real; NAME, a choice. */
    private static String label(Setting<?> s) {
        return s.type() == Integer.class ? "N" : s.type() == Double.class ? "X" : "NAME";
    }
}
