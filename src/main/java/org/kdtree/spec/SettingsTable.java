package org.kdtree.spec;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.kdtree.accel.Setting;

/**
 * The one table of builder settings: every row that a builder known by name takes
 * ({@link BuilderSpec#names()}), each declared once by its owner (the shared rows in
 * {@code accel.SharedSettings}, the SAH's in {@code SahSettings}, the BVH's width in
 * {@code BvhBuilder}, a plug-in's in its own class). The command line's options, the workbench's
 * controls and docs/limits.md are made from it, so a plug-in's rows join them when it is loaded.
 * {@link BuilderSpec} is its public face.
 */
final class SettingsTable {
    private SettingsTable() {
    }

    /**
     * {@return every row of every builder known by name, once each}: the builders' rows in the
     * order the builders are known and list them, so the SAH's preset comes first (a spec applies
     * it first, and the other rows override it)
     */
    static List<Setting<?>> all() {
        Set<Setting<?>> rows = new LinkedHashSet<>();
        Map<String, String> ownerOfOption = new HashMap<>();
        for (String name : BuilderSpec.names()) {
            for (Setting<?> row : BuilderSpec.settingRows(name)) {
                if (!rows.add(row)) continue;
                String before = ownerOfOption.putIfAbsent(row.option(), name);
                if (before != null)
                    throw new IllegalArgumentException("the " + name + " builder declares a setting " + row.option()
                            + " of its own, but the " + before + " builder's " + row.option() + " is another setting: give it another option");
            }
        }
        return List.copyOf(rows);
    }

    /** {@return the names of the builders known by name that take {@code row}} */
    static List<String> takers(Setting<?> row) {
        List<String> names = new ArrayList<>();
        for (String name : BuilderSpec.names()) if (BuilderSpec.settingRows(name).contains(row)) names.add(name);
        return names;
    }

    /**
     * {@return the builders {@code row} applies to, as a message says it}: "every builder", "the
     * kd-tree builders", "the sah builder", "the sah and bvh builders"
     *
     * @param row a row of the table
     */
    static String ownerName(Setting<?> row) {
        List<String> takers = takers(row);
        if (takers.size() == BuilderSpec.names().size()) return "every builder";
        if (takers.equals(new ArrayList<>(Builders.names()))) return "the kd-tree builders";
        if (takers.size() == 1) return "the " + takers.get(0) + " builder";
        return "the " + String.join(", ", takers.subList(0, takers.size() - 1)) + " and " + takers.get(takers.size() - 1) + " builders";
    }

    /**
     * {@return whether some kd-tree builder takes {@code row}} (a command that needs a kd-tree offers only those)
     *
     * @param row a row of the table
     */
    static boolean takenByKdTrees(Setting<?> row) {
        for (String name : Builders.names()) if (Builders.settingRows(name).contains(row)) return true;
        return false;
    }

    /**
     * {@return whether every builder known by name takes {@code row}}
     *
     * @param row a row of the table
     */
    static boolean appliesToEvery(Setting<?> row) {
        return takers(row).size() == BuilderSpec.names().size();
    }
}
