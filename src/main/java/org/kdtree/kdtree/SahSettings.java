package org.kdtree.kdtree;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.function.Function;
import java.util.stream.Collectors;
import org.kdtree.accel.Setting;
import org.kdtree.accel.Settings;
import org.kdtree.accel.SharedSettings;
import org.kdtree.kdtree.SahBuilder.Algorithm;
import org.kdtree.limits.Limits;

/**
 * The SAH builder's own setting rows (docs/limits.md lists them), declared here once, and how a
 * named preset ({@link Quality}) fills the rows not given: the specification of
 * {@link SahBuilder}, kept apart from its two questions.
 */
public final class SahSettings {
    private SahSettings() {
    }

    /** A named preset (plane search and leaf size); first of the rows, so that the others, if given, override it. */
    public static final Setting<Quality> QUALITY = Setting.choice("quality", "--quality", Quality.class, null,
            "a named SAH preset, " + Arrays.stream(Quality.values())
                    .map(q -> q.name().toLowerCase(Locale.ROOT) + " (" + q.describe() + ")")
                    .collect(Collectors.joining(", ")) + "; the other settings, if given, override it");
    /** lambda, the weight of a plane that leaves one child empty. */
    public static final Setting<Double> LAMBDA = Setting.real("--lambda", Limits.LAMBDA, 0.8,
            "the SAH's weight of a plane that cuts off empty space (1 = no bonus)");
    /** The plane search. */
    public static final Setting<Algorithm> ALGORITHM = Setting.choice("plane search", "--algorithm", Algorithm.class, Algorithm.EVENT,
            "how the SAH searches for its planes (NAIVE, SORTED and EVENT build the same tree in different times; "
                    + "BINNED builds another, with planes at bin boundaries only)");
    /** The node size below which the binned search sweeps exactly. */
    public static final Setting<Integer> EXACT_BELOW = Setting.whole("--exact-below", Limits.EXACT_BELOW, 64,
            "the BINNED plane search sweeps nodes of fewer references exactly");
    /** The smallest node searched for a plane. */
    public static final Setting<Integer> LEAF_BELOW = Setting.whole("--leaf-below", Limits.LEAF_BELOW, 1,
            "nodes of fewer references become leaves without a plane search (1 = only empty ones)");
    /** Splits still made along a path past the leaf criterion, on trial. */
    public static final Setting<Integer> LOOKAHEAD = Setting.whole("--lookahead", Limits.LOOKAHEAD, 0,
            "splits still made along a path where no plane beats the leaf (the talk's \"a few more iterations\"); "
                    + "each subtree is kept only where it ends cheaper than the leaf");

    /** The preset first, then every kd-tree builder's rows, then the SAH's own. */
    static final List<Setting<?>> ROWS = rows();

    private static List<Setting<?>> rows() {
        List<Setting<?>> rows = new ArrayList<>();
        rows.add(QUALITY);
        rows.addAll(KdTreeBuilder.ROWS);
        rows.addAll(List.of(LAMBDA, ALGORITHM, SharedSettings.BINS, EXACT_BELOW, LEAF_BELOW, LOOKAHEAD));
        return List.copyOf(rows);
    }

    /** The rows a preset sets: dropped when one is given, so that only rows given after it override it. */
    private static final List<Setting<?>> PRESET_ROWS = List.of(ALGORITHM, SharedSettings.BINS, EXACT_BELOW, LEAF_BELOW,
            SharedSettings.MAX_DEPTH);

    /** {@code s} with the preset {@code q} and without the rows it sets. */
    static Settings withQuality(Settings s, Quality q) {
        for (Setting<?> row : PRESET_ROWS) s = s.with(row, null);
        return s.with(QUALITY, q);
    }

    /** {@return the plane search: as given, else the preset's, else EVENT} */
    static Algorithm algorithm(Settings s) { return givenOrPreset(s, ALGORITHM, Quality::algorithm); }

    /** {@return the binned search's exact threshold: as given, else the preset's, else 64} */
    static int exactBelow(Settings s) { return givenOrPreset(s, EXACT_BELOW, q -> q.exactBelow() >= 0 ? q.exactBelow() : null); }

    /** {@return the smallest node searched for a plane: as given, else the preset's, else 1} */
    static int leafBelow(Settings s) { return givenOrPreset(s, LEAF_BELOW, Quality::leafBelow); }

    /** A row's value as given, else the preset's (where it sets one), else the row's default. */
    private static <T> T givenOrPreset(Settings s, Setting<T> row, Function<Quality, T> ofPreset) {
        T given = s.given(row);
        if (given != null) return given;
        Quality preset = s.given(QUALITY);
        T value = preset != null ? ofPreset.apply(preset) : null;
        return value != null ? value : row.defaultValue();
    }
}
