package org.kdtree.accel;

import java.util.List;
import java.util.Objects;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Function;
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
 * own beside its code (the SAH's lambda in {@code SahSettings}, the BVH's width in
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

    /**
     * {@return the command-line option that gives it}, e.g. {@code --lambda}; the library's errors
     * name the setting by its {@link #name()}, and the command line words them with this ({@link Refused#message})
     */
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
     * @throws Refused if it is out of range or of another type (the message names the setting by
     *         its {@link #name()}: "lambda must be between 0.01 and 1, got 2")
     */
    public T check(Object value) {
        if (value == null) throw new Refused(List.of(this), n -> n.apply(this) + " needs a value, got null");
        if (!type.isInstance(value))
            throw new Refused(List.of(this), n -> n.apply(this) + " takes " + type.getSimpleName() + ", got " + value.getClass().getSimpleName());
        if (limit != null && !limit.allows(((Number) value).doubleValue()))
            throw new Refused(List.of(this), n -> limit.rejection(n.apply(this), format(value)));
        return type.cast(value);
    }

    /**
     * A setting's value refused, or a setting refused by a builder that does not take it. The
     * message names each setting as a library user knows it, by its {@link #name()} ("lambda must
     * be between 0.01 and 1, got 2", "lambda applies to the sah builder only, not to
     * median-plane"); whoever gave the settings another way words the same refusal with its own
     * names ({@link #message}): the command line by the options the user typed ("--lambda must be
     * between ...").
     */
    public static final class Refused extends IllegalArgumentException {
        private static final long serialVersionUID = 1L;
        /** The settings refused. */
        private final transient List<Setting<?>> settings;
        /** The message, given how to name a setting. */
        private final transient Function<Function<Setting<?>, String>, String> wording;

        /**
         * A refusal of {@code settings}, in words that name them as {@code wording}'s argument does.
         *
         * @param settings the settings refused
         * @param wording  the message, given how to name each setting
         */
        public Refused(List<Setting<?>> settings, Function<Function<Setting<?>, String>, String> wording) {
            super(wording.apply(Setting::name));
            this.settings = List.copyOf(settings);
            this.wording = wording;
        }

        /** {@return the settings refused} */
        public List<Setting<?>> settings() { return settings; }

        /**
         * {@return the message with each setting named by {@code naming}}, e.g. {@code Setting::option} for the command line
         *
         * @param naming how the caller names a setting
         */
        public String message(Function<Setting<?>, String> naming) {
            return wording.apply(naming);
        }
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

    /** {@return its name}, as the library's messages name it */
    @Override public String toString() { return name; }
}
