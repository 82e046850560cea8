package org.kdtree.limits;

import java.util.Locale;

/**
 * One setting's allowed range, stated once in {@link Limits} and checked by whoever receives the
 * value: the API's setters, the command line's options, the scene files' fields and the
 * workbench's spinners. Each caller names the value its own way ({@code --threads},
 * {@code $.camera.width}, {@code Kmaxdepth}); the range and the wording are the same.
 *
 * @param title   what the value is, for tables and tooltips ("threads", "Kt")
 * @param min     the smallest allowed value
 * @param max     the largest allowed value
 * @param integer whether only whole numbers are allowed
 * @param note    what special values mean, or "" (for example "-1 = auto")
 */
public record Limit(String title, double min, double max, boolean integer, String note) {
    /**
     * Checks that the range is not empty.
     *
     * @param title   what the value is, for tables and tooltips
     * @param min     the smallest allowed value
     * @param max     the largest allowed value, at least {@code min}
     * @param integer whether only whole numbers are allowed
     * @param note    what special values mean, or ""
     * @throws IllegalArgumentException if {@code min > max} or either is NaN
     */
    public Limit {
        if (!(min <= max)) throw new IllegalArgumentException(title + ": empty range " + min + ".." + max);
    }

    /**
     * A whole-number setting in {@code [min, max]}.
     *
     * @param title what the value is
     * @param min   the smallest allowed value
     * @param max   the largest allowed value
     * @return the limit, without a note
     */
    public static Limit whole(String title, long min, long max) {
        return new Limit(title, min, max, true, "");
    }

    /**
     * A real-valued setting in {@code [min, max]}.
     *
     * @param title what the value is
     * @param min   the smallest allowed value
     * @param max   the largest allowed value
     * @return the limit, without a note
     */
    public static Limit real(String title, double min, double max) {
        return new Limit(title, min, max, false, "");
    }

    /**
     * The same limit, with a note on what a special value means.
     *
     * @param text the note, for example "-1 = auto"
     * @return a new limit with the same range and {@code text} as its note
     */
    public Limit noting(String text) {
        return new Limit(title, min, max, integer, text);
    }

    /**
     * Whether {@code value} is allowed (never for NaN, nor for a fraction where a whole number is due).
     *
     * @param value the value to test
     * @return true if {@code value} is in range (and whole, where that is due)
     */
    public boolean allows(double value) {
        return value >= min && value <= max && (!integer || value == Math.rint(value));
    }

    /**
     * {@code value}, if allowed; otherwise an error saying that {@code where} must be in range.
     *
     * @param where how the caller names the value ({@code --threads}, {@code $.camera.width})
     * @param value the value to check
     * @return {@code value}, unchanged
     * @throws IllegalArgumentException if {@code value} is not allowed
     */
    public int check(String where, int value) {
        if (!allows(value)) throw new IllegalArgumentException(rejection(where, Integer.toString(value)));
        return value;
    }

    /**
     * {@code value}, if allowed; otherwise an error saying that {@code where} must be in range.
     *
     * @param where how the caller names the value ({@code --threads}, {@code $.camera.width})
     * @param value the value to check
     * @return {@code value}, unchanged
     * @throws IllegalArgumentException if {@code value} is not allowed
     */
    public double check(String where, double value) {
        if (!allows(value)) throw new IllegalArgumentException(rejection(where, format(value)));
        return value;
    }

    /**
     * The one wording of a rejection: "{@code where} must be between 1 and 256, got 0".
     *
     * @param where how the caller names the value
     * @param got   the rejected value, as written
     * @return the message, {@code where}, the {@link #requirement()} and {@code got}
     */
    public String rejection(String where, String got) {
        return where + " " + requirement() + ", got " + got;
    }

    /** {@return "must be between 1 and 256", with the note if any} */
    public String requirement() {
        return "must be between " + format(min) + " and " + format(max)
                + (note.isEmpty() ? "" : " (" + note + ")");
    }

    /** {@return the range as people write it: "1..256", with the note if any} */
    public String range() {
        return format(min) + ".." + format(max) + (note.isEmpty() ? "" : " (" + note + ")");
    }

    /**
     * Whole numbers without a decimal point, reals as short as they print exactly.
     *
     * @param v the value to write
     * @return {@code v} as a whole number if it is one (below 1e15 in magnitude), else as
     *         {@link Double#toString} writes it, in lower case
     */
    public static String format(double v) {
        if (v == Math.rint(v) && Math.abs(v) < 1e15) return Long.toString((long) v);
        return Double.toString(v).toLowerCase(Locale.ROOT);
    }
}
