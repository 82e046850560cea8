package org.kdtree.cli;

import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParseException;
import com.google.gson.stream.JsonReader;
import java.io.IOException;
import java.io.StringReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.kdtree.check.Contract;
import org.kdtree.check.ContractCase;
import org.kdtree.check.QualityChecks;

/**
 * A teacher's rubric: the points and the visibility of each check a grade makes. The pass/fail
 * checks (the contract's cases, the quality tier's checks) earn their points when they pass; the
 * two measured ones ({@value #COST} and {@value #TIME}: the student's trees against the library's
 * SAH, geometric mean over the course scenes) earn all of theirs at a ratio of {@code full_at} or
 * less, none at {@code zero_at} or more, and a straight-line share between.
 *
 * <p>The file is JSON: {@code {"visibility": "visible", "checks": {"talk figures": {"points": 2}, ...,
 * "expected cost vs the SAH": {"points": 10, "full_at": 1.1, "zero_at": 2}}}}. A check it does
 * not name is worth nothing; a name that is no check is refused (a typo would lose its points).
 */
final class Rubric {
    /** The measured checks: the student's expected cost, and build time, over the library's SAH's. */
    static final String COST = "expected cost vs the SAH", TIME = "build time vs the SAH";
    /** Gradescope's visibilities (its results.json's words), which a rubric uses too. */
    static final List<String> VISIBILITIES = List.of("visible", "hidden", "after_due_date", "after_published");

    /**
     * One check's worth.
     *
     * @param check      the check's name, as the grade reports it
     * @param points     what it is worth
     * @param visibility when a student sees it (Gradescope's word)
     * @param fullAt     a measured check's ratio at or below which it earns all its points, else NaN
     * @param zeroAt     a measured check's ratio at or above which it earns none, else NaN
     */
    record Item(String check, double points, String visibility, double fullAt, double zeroAt) {
        boolean measured() {
            return !Double.isNaN(fullAt);
        }

        /** The points a measured ratio earns: all up to {@code fullAt}, none from {@code zeroAt}, a straight line between. */
        double earned(double ratio) {
            if (Double.isNaN(ratio)) return 0;
            double share = (zeroAt - ratio) / (zeroAt - fullAt);
            return round(points * Math.max(0, Math.min(1, share)));
        }
    }

    private final List<Item> items;

    private Rubric(List<Item> items) {
        this.items = List.copyOf(items);
    }

    /** {@return every check's worth, in the order the grade makes them} */
    List<Item> items() {
        return items;
    }

    /** {@return the most points a submission can earn} */
    double maxScore() {
        return round(items.stream().mapToDouble(Item::points).sum());
    }

    /** {@return the pass/fail checks a grade makes: the contract's cases, then the quality tier's, in the report's order} */
    static List<String> passFailChecks() {
        List<String> names = new ArrayList<>();
        for (ContractCase c : Contract.cases()) names.add(c.name());
        for (ContractCase c : Contract.randomCases()) names.add(c.name());
        names.addAll(QualityChecks.NAMES);
        return names;
    }

    /** {@return every check's name: the pass/fail ones, then the measured ones} */
    static List<String> checks() {
        List<String> names = new ArrayList<>(passFailChecks());
        names.addAll(List.of(COST, TIME));
        return names;
    }

    /**
     * The rubric when the teacher gives none: one point for each pass/fail check, the measured
     * ones worth nothing (they are still reported), everything visible.
     */
    static Rubric onePointEach() {
        List<Item> items = new ArrayList<>();
        for (String c : passFailChecks()) items.add(new Item(c, 1, "visible", Double.NaN, Double.NaN));
        items.add(new Item(COST, 0, "visible", 1, 2));
        items.add(new Item(TIME, 0, "visible", 1, 10));
        return new Rubric(items);
    }

    /**
     * Reads a rubric file; anything wrong in it is one line naming the file and the field.
     *
     * @param option the option that named the file ({@code --rubric})
     * @param file the file
     * @return the rubric
     */
    static Rubric read(String option, Path file) {
        String where = option + " " + file;
        if (Files.isDirectory(file)) throw new IllegalArgumentException(where + ": is a folder, not a file");
        String text;
        try {
            text = Files.readString(file, StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new IllegalArgumentException(where + (Files.exists(file) ? ": cannot be read (" + e.getMessage() + ")" : ": no such file"));
        }
        JsonElement root;
        try {
            JsonReader in = new JsonReader(new StringReader(text));   // strict (JsonParser would make it lenient): no comments, no trailing comma
            root = new com.google.gson.Gson().getAdapter(JsonElement.class).read(in);
            if (in.peek() != com.google.gson.stream.JsonToken.END_DOCUMENT) throw new JsonParseException("content after the end");
        } catch (JsonParseException | IOException | IllegalStateException e) {
            throw new IllegalArgumentException(where + ": not a JSON rubric (" + firstLine(e.getMessage()) + ")");
        }
        return parse(where, root);
    }

    private static Rubric parse(String where, JsonElement root) {
        if (!root.isJsonObject()) throw new IllegalArgumentException(where + ": a rubric is a JSON object {\"checks\": {...}}");
        JsonObject top = root.getAsJsonObject();
        allowOnly(where, "the rubric", top, Set.of("checks", "visibility", "title"));
        String visibility = top.has("visibility") ? visibility(where, "visibility", top.get("visibility")) : "visible";
        if (!top.has("checks") || !top.get("checks").isJsonObject())
            throw new IllegalArgumentException(where + ": checks: missing; give {\"checks\": {\"CHECK\": {\"points\": N}, ...}}");
        Map<String, JsonObject> given = new LinkedHashMap<>();
        for (Map.Entry<String, JsonElement> e : top.getAsJsonObject("checks").entrySet()) {
            String field = "checks.\"" + e.getKey() + "\"";
            if (!checks().contains(e.getKey()))
                throw new IllegalArgumentException(where + ": " + field + ": no such check; the checks are: " + String.join(", ", checks()));
            if (!e.getValue().isJsonObject())
                throw new IllegalArgumentException(where + ": " + field + ": must be an object such as {\"points\": 2}");
            given.put(e.getKey(), e.getValue().getAsJsonObject());
        }
        List<Item> items = new ArrayList<>();
        for (String check : checks()) {
            JsonObject o = given.get(check);
            boolean measured = check.equals(COST) || check.equals(TIME);
            if (o == null) {
                items.add(new Item(check, 0, visibility, measured ? 1 : Double.NaN, measured ? 2 : Double.NaN));
                continue;
            }
            items.add(item(where, "checks.\"" + check + "\"", check, o, visibility, measured));
        }
        return new Rubric(items);
    }

    private static Item item(String where, String field, String check, JsonObject o, String visibility, boolean measured) {
        allowOnly(where, field, o, measured ? Set.of("points", "visibility", "full_at", "zero_at") : Set.of("points", "visibility"));
        if (!o.has("points")) throw new IllegalArgumentException(where + ": " + field + ".points: missing; give the points it is worth");
        double points = number(where, field + ".points", o.get("points"), 0);
        String v = o.has("visibility") ? visibility(where, field + ".visibility", o.get("visibility")) : visibility;
        if (!measured) return new Item(check, points, v, Double.NaN, Double.NaN);
        for (String f : List.of("full_at", "zero_at"))
            if (!o.has(f)) throw new IllegalArgumentException(where + ": " + field + "." + f + ": missing; a measured check needs "
                    + "full_at (the ratio to the SAH's that earns all its points) and zero_at (the ratio that earns none)");
        double full = number(where, field + ".full_at", o.get("full_at"), 0), zero = number(where, field + ".zero_at", o.get("zero_at"), 0);
        if (!(zero > full)) throw new IllegalArgumentException(where + ": " + field + ".zero_at: must be greater than full_at (" + full + "), got " + zero);
        return new Item(check, points, v, full, zero);
    }

    private static void allowOnly(String where, String what, JsonObject o, Set<String> known) {
        for (String name : o.keySet())
            if (!known.contains(name))
                throw new IllegalArgumentException(where + ": " + (what.equals("the rubric") ? "" : what + ".") + name
                        + ": no such field; " + what + " takes " + String.join(", ", known.stream().sorted().toList()));
    }

    private static double number(String where, String field, JsonElement e, double min) {
        double v;
        try {
            if (!e.isJsonPrimitive() || !e.getAsJsonPrimitive().isNumber()) throw new NumberFormatException();
            v = e.getAsDouble();
        } catch (NumberFormatException | UnsupportedOperationException | IllegalStateException notANumber) {
            throw new IllegalArgumentException(where + ": " + field + ": must be a number, got " + e);
        }
        if (!(v >= min) || Double.isInfinite(v) || v > 1e6)
            throw new IllegalArgumentException(where + ": " + field + ": must be from " + (int) min + " to 1000000, got " + e);
        return v;
    }

    private static String visibility(String where, String field, JsonElement e) {
        String v = e.isJsonPrimitive() && e.getAsJsonPrimitive().isString() ? e.getAsString() : null;
        if (v == null || !VISIBILITIES.contains(v))
            throw new IllegalArgumentException(where + ": " + field + ": must be one of " + String.join(", ", VISIBILITIES) + ", got " + e);
        return v;
    }

    private static String firstLine(String s) {
        if (s == null) return "malformed JSON";
        return s.replaceFirst("^com\\.google\\.gson\\.stream\\.MalformedJsonException: ", "")
                .replaceFirst("Use JsonReader\\.setLenient\\(true\\) to accept malformed JSON", "malformed JSON")
                .replaceFirst("\\s*See https://github.com/google/gson\\S*", "").split("\\R", 2)[0];
    }

    /** Points to two decimals, as a teacher's sheet takes them. */
    static double round(double points) {
        return Math.round(points * 100) / 100.0;
    }
}
