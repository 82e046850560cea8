package org.kdtree.cli;

import com.google.gson.GsonBuilder;
import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import java.util.Locale;

/**
 * One student's grade as Gradescope's autograder reads it ({@code /autograder/results/results.json},
 * its "Autograder Specifications"): the total {@code score}, {@code execution_time} in seconds, an
 * {@code output} for the whole submission, one entry of {@code tests} per check of the rubric
 * ({@code name}, {@code score}, {@code max_score}, {@code status}, {@code output}, {@code visibility}),
 * and the trees' quality and build time as {@code leaderboard} entries (lower is better: {@code "order": "asc"}).
 */
final class GradescopeResults {
    private GradescopeResults() {
    }

    /** {@return results.json of {@code card}} */
    static String of(Scorecard card, Report report) {
        StudentRow r = card.row();
        JsonObject root = new JsonObject();
        root.addProperty("score", card.score());
        root.addProperty("execution_time", (long) Math.ceil(r.seconds()));
        root.addProperty("output", output(card, report));
        JsonArray tests = new JsonArray();
        for (Scorecard.Scored k : card.checks()) {
            JsonObject t = new JsonObject();
            t.addProperty("name", k.check());
            t.addProperty("score", k.score());
            t.addProperty("max_score", k.max());
            t.addProperty("status", k.passed() ? "passed" : "failed");
            t.addProperty("output", k.output());
            t.addProperty("visibility", k.visibility());
            tests.add(t);
        }
        root.add("tests", tests);
        if (report != null && !Double.isNaN(Scorecard.costRatio(report.rows()))) {
            JsonArray board = new JsonArray();
            board.add(entry("expected cost / SAH's", round3(Scorecard.costRatio(report.rows()))));
            board.add(entry("build time / SAH's", round3(Scorecard.timeRatio(report.rows()))));
            root.add("leaderboard", board);
        }
        return new GsonBuilder().setPrettyPrinting().disableHtmlEscaping().create().toJson(root) + "\n";
    }

    private static JsonObject entry(String name, double value) {
        JsonObject e = new JsonObject();
        e.addProperty("name", name);
        e.addProperty("value", value);
        e.addProperty("order", "asc");
        return e;
    }

    /** The verdict and what went wrong with the run, for the whole submission. */
    private static String output(Scorecard card, Report report) {
        StudentRow r = card.row();
        StringBuilder s = new StringBuilder(String.format(Locale.ROOT, "builder %s: %s; %s%n",
                r.builder().isEmpty() ? "(none graded)" : r.builder(), report != null ? report.verdict() : r.verdict() + ": " + r.problem(),
                card.line()));
        if (report != null && !r.problem().isEmpty()) s.append("your JVM: ").append(r.problem()).append('\n');
        s.append("graded outside your builder's JVM, from the trees it built").append(r.unboxed() ? ", without a box (--no-sandbox)" : ", in a box")
                .append('\n');
        return s.toString();
    }

    private static double round3(double v) {
        return Math.round(v * 1000) / 1000.0;
    }
}
