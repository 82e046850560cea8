package org.kdtree.accel;

import java.util.Objects;
import java.util.concurrent.atomic.AtomicInteger;
import org.kdtree.limits.Limit;
import org.kdtree.limits.Limits;

/**
 * One setting a builder takes, declared once by whoever owns it: its name, its command-line
 * option, its default, its {@link Limits} entry (for a number), and a line of help. A builder
 * lists the rows it takes ({@link StructureBuilder#settingRows()}) and reads their values from one
 * immutable {@link Settings} value; the command line's options, the workbench's controls and the
 * table in docs/limits.md are made from the rows of every builder known by name.
 *
 * <p>The rows that both structures take are {@link SharedSettings}'; each builder declares its
 * own beside its code (the SAH's lambda in {@code SahBuilder}, the BVH's width in
 * {@code BvhBuilder}), and a plug-in's builder may declare rows of its own the same way.
 *
 * @param <T> the value's type: Double, Integer, Boolean or an enum
 */
public final class Setting<T> {
    private static final AtomicInteger NEXT_ID = new AtomicInteger();

    private final int id = NEXT_ID.getAndIncrement();
    private final String name;
    private final String option;
    private final Class<T> type;
    private final T defaultValue;
    private final Limit limit;
    private final String help;

    private Setting(String name, String option, Class<T> type, T defaultValue, Limit limit, String help) {
        this.name = Objects.requireNonNull(name, "name");
        this.option = Objects.requireNonNull(option, "option");
        if (!option.matches("--[a-z][a-z0-9-]*")) throw new IllegalArgumentException("a setting's option is --lower-case-words, got " + option);
        this.type = Objects.requireNonNull(type, "type");
        this.defaultValue = defaultValue;
        this.limit = limit;
        this.help = Objects.requireNonNull(help, "help");
        if (limit != null) check(defaultValue);
    }

    /**
     * {@return a whole-number setting named by its limit's title}
     *
     * @param option       its command-line option, e.g. {@code --leaf-size}
     * @param limit        its allowed range (a whole number)
     * @param defaultValue the value a builder starts from
     * @param help         one line on what it does
     */
    public static Setting<Integer> whole(String option, Limit limit, int defaultValue, String help) {
        return new Setting<>(limit.title(), option, Integer.class, defaultValue, limit, help);
    }

    /**
     * {@return a real-number setting named by its limit's title}
     *
     * @param option       its command-line option, e.g. {@code --lambda}
     * @param limit        its allowed range
     * @param defaultValue the value a builder starts from
     * @param help         one line on what it does
     */
    public static Setting<Double> real(String option, Limit limit, double defaultValue, String help) {
        return new Setting<>(limit.title(), option, Double.class, defaultValue, limit, help);
    }

    /**
     * {@return a setting that is one of an enum's constants}
     *
     * @param name         what it is called, e.g. "plane search"
     * @param option       its command-line option
     * @param type         the enum
     * @param defaultValue the value a builder starts from, or null for none (a preset)
     * @param help         one line on what it does
     * @param <E>          the enum
     */
    public static <E extends Enum<E>> Setting<E> choice(String name, String option, Class<E> type, E defaultValue, String help) {
        return new Setting<>(name, option, type, defaultValue, null, help);
    }

    /**
     * {@return an on/off setting; its option switches it away from its default}
     *
     * @param name         what it is called, e.g. "perfect splits"
     * @param option       its command-line option, e.g. {@code --no-perfect-splits}
     * @param defaultValue the value a builder starts from
     * @param help         one line on what it does
     */
    public static Setting<Boolean> onOff(String name, String option, boolean defaultValue, String help) {
        return new Setting<>(name, option, Boolean.class, defaultValue, null, help);
    }

    /** Its index in a {@link Settings} value: rows are numbered as they are made. */
    int id() { return id; }

    /** {@return what the setting is called, in the talk's words where it has one}, e.g. "lambda", "Kmaxdepth" */
    public String name() { return name; }

    /** {@return the command-line option that gives it}, e.g. {@code --lambda}; errors name the setting by it */
    public String option() { return option; }

    /** {@return the type of its value}: Double, Integer, Boolean or an enum */
    public Class<T> type() { return type; }

    /** {@return the value a builder starts from}, null for a preset (none is applied unless given) */
    public T defaultValue() { return defaultValue; }

    /** {@return its allowed range}, null for a setting that is not a number */
    public Limit limit() { return limit; }

    /** {@return one line on what it does}, without its range or default (each reader adds those its own way) */
    public String help() { return help; }

    /**
     * {@code value}, checked against this setting's range: the one range check of every setting.
     *
     * @param value the value, not null
     * @return {@code value}
     * @throws IllegalArgumentException if it is out of range (the message names {@link #option()}) or of another type
     */
    public T check(Object value) {
        Objects.requireNonNull(value, option);
        if (!type.isInstance(value))
            throw new IllegalArgumentException(option + " takes " + type.getSimpleName() + ", got " + value.getClass().getSimpleName());
        if (limit != null) limit.check(option, ((Number) value).doubleValue());
        return type.cast(value);
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
