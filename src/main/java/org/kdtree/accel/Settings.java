package org.kdtree.accel;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Objects;

/**
 * A builder's settings as one immutable value: the rows given a value, each checked against its
 * range once, when given ({@link Setting#check}); every other row reads as its default. A builder
 * holds one and reads it ({@link #get}); the command line, the workbench and the studies make
 * one and hand it over whole ({@link StructureBuilder#configure}).
 */
public final class Settings {
    /** No setting given: every row reads as its default. */
    public static final Settings DEFAULTS = new Settings(new Object[0], List.of());

    /** Values by {@link Setting#id()}; null where not given. */
    private final Object[] values;
    /** The rows given, in the order they were given. */
    private final List<Setting<?>> given;

    private Settings(Object[] values, List<Setting<?>> given) {
        this.values = values;
        this.given = given;
    }

    /**
     * {@return the value given for {@code setting}, or else its default}
     *
     * @param setting the row
     * @param <T>     its type
     */
    public <T> T get(Setting<T> setting) {
        T v = given(setting);
        return v != null ? v : setting.defaultValue();
    }

    /**
     * {@return the value given for {@code setting}, or null}
     *
     * @param setting the row
     * @param <T>     its type
     */
    @SuppressWarnings("unchecked")
    public <T> T given(Setting<T> setting) {
        int id = setting.id();
        return id < values.length ? (T) values[id] : null;
    }

    /** {@return the rows given a value, in the order they were given} */
    public List<Setting<?>> givenRows() { return given; }

    /**
     * {@return these settings with {@code setting} given as {@code value}, or no longer given if {@code value} is null}
     *
     * @param setting the row
     * @param value   its value, checked against the row's range
     * @param <T>     its type
     * @throws Setting.Refused if the value is out of range (naming the setting by its {@link Setting#name()})
     */
    public <T> Settings with(Setting<T> setting, T value) {
        int id = setting.id();
        Object[] v = Arrays.copyOf(values, Math.max(values.length, id + 1));
        List<Setting<?>> g = new ArrayList<>(given);
        g.remove(setting);
        if (value == null) {
            v[id] = null;
        } else {
            v[id] = setting.check(value);
            g.add(setting);
        }
        return new Settings(v, List.copyOf(g));
    }

    /**
     * {@return these settings with every row {@code more} gives, over these}
     *
     * @param more the settings that win
     */
    public Settings with(Settings more) {
        Settings s = this;
        for (Setting<?> row : more.given) s = s.withRaw(row, more.given(row));
        return s;
    }

    private <T> Settings withRaw(Setting<T> row, Object value) {
        return with(row, row.type().cast(value));
    }

    /**
     * {@return only the rows of these settings that {@code rows} holds}
     *
     * @param rows the rows to keep
     */
    public Settings only(List<Setting<?>> rows) {
        Settings s = DEFAULTS;
        for (Setting<?> row : given) if (rows.contains(row)) s = s.withRaw(row, given(row));
        return s;
    }

    @Override public boolean equals(Object o) {
        if (!(o instanceof Settings s) || s.given.size() != given.size()) return false;
        for (Setting<?> row : given) if (!Objects.equals(given(row), s.given(row))) return false;
        return true;
    }

    @Override public int hashCode() {
        int h = 0;
        for (Setting<?> row : given) h += row.hashCode() ^ Objects.hashCode(given(row));
        return h;
    }

    /** {@return the given rows as options}, e.g. {@code --lambda 0.5 --no-perfect-splits} (a switch only when off its default) */
    @Override public String toString() {
        List<String> parts = new ArrayList<>();
        for (Setting<?> row : given) {
            Object v = given(row);
            if (!(v instanceof Boolean)) parts.add(row.option() + " " + v);
            else if (!v.equals(row.defaultValue())) parts.add(row.option());
        }
        return String.join(" ", parts);
    }
}
