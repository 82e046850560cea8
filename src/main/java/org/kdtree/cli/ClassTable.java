package org.kdtree.cli;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;

/** {@code grade-class}'s table: one row per jar, failures first, then by file name; as CSV and as Markdown with a summary. */
final class ClassTable {
    private static final List<String> ORDER = List.of("FAIL", "CORRECT", "GOOD");
    /** The note of every row graded without a box. */
    static final String UNBOXED = "not boxed (--no-sandbox)";
    private final List<StudentRow> rows;
    private final List<String> scenes;
    /** Each row's score by the rubric, by file name; empty without a rubric (no score column then). */
    private final Map<String, Scorecard> scores;
    /** What the roster and the folder disagree on, one line each (below the Markdown table). */
    private final List<String> rosterLines;

    /** @param scenes the course scenes' names, the CSV's per-scene columns */
    ClassTable(List<StudentRow> rows, List<String> scenes) {
        this(rows, scenes, Map.of(), List.of());
    }

    /**
     * @param scenes      the course scenes' names, the CSV's per-scene columns
     * @param scores      each row's score by the rubric, by file name, or empty
     * @param rosterLines what the roster and the folder disagree on
     */
    ClassTable(List<StudentRow> rows, List<String> scenes, Map<String, Scorecard> scores, List<String> rosterLines) {
        this.rows = new ArrayList<>(rows);
        this.rows.sort(Comparator.comparingInt((StudentRow r) -> ORDER.indexOf(r.verdict())).thenComparing(StudentRow::file));
        this.scenes = scenes;
        this.scores = scores;
        this.rosterLines = rosterLines;
    }

    /** "31.5", the row's score, or "" without a rubric. */
    private String score(StudentRow r) {
        Scorecard c = scores.get(r.file());
        return c == null ? "" : Scorecard.points(c.score());
    }

    List<StudentRow> rows() {
        return rows;
    }

    /** "10 jars: 7 FAIL, 1 CORRECT, 2 GOOD". */
    String summary() {
        Map<String, Integer> n = new TreeMap<>(Comparator.comparingInt(ORDER::indexOf));
        for (String v : ORDER) n.put(v, 0);
        for (StudentRow r : rows) n.merge(r.verdict(), 1, Integer::sum);
        List<String> parts = new ArrayList<>();
        n.forEach((v, k) -> parts.add(k + " " + v));
        return rows.size() + " jars: " + String.join(", ", parts);
    }

    String csv() {
        StringBuilder s = new StringBuilder("file,student,id,builder,verdict," + (scores.isEmpty() ? "" : "score,")
                + "first_failure,quality_failed,problem,cost_vs_median,cost_vs_sah,build_ms,seconds,box");
        for (String scene : scenes) s.append(',').append(quote("vs_median " + scene)).append(',').append(quote("vs_sah " + scene));
        s.append('\n');
        for (StudentRow r : rows) {
            s.append(String.join(",", quote(r.file()), quote(r.student()), quote(r.id()), quote(r.builder()), r.verdict()
                            + (scores.isEmpty() ? "" : "," + score(r)), quote(r.failure()),
                    quote(r.quality()), quote(r.problem()), num(r.meanRatio(0)), num(r.meanRatio(1)),
                    r.ratios().isEmpty() ? "" : String.format(Locale.ROOT, "%.1f", r.buildMs()), String.format(Locale.ROOT, "%.1f", r.seconds()), r.box()));
            for (String scene : scenes) {
                double[] q = r.ratios().get(scene);
                s.append(',').append(q == null ? "" : num(q[0])).append(',').append(q == null ? "" : num(q[1]));
            }
            s.append('\n');
        }
        return s.toString();
    }

    String markdown() {
        String max = scores.isEmpty() ? "" : Scorecard.points(scores.values().iterator().next().maxScore());
        StringBuilder s = new StringBuilder("# Class grades\n\n**" + summary() + "**\n\n"
                + "| file | student | id | builder | verdict | " + (scores.isEmpty() ? "" : "score (of " + max + ") | ")
                + "cost vs median | cost vs SAH | build ms | first failure, quality failed, problem |\n"
                + "| --- | --- | --- | --- | --- | " + (scores.isEmpty() ? "" : "---: | ") + "---: | ---: | ---: | --- |\n");
        for (StudentRow r : rows) {
            List<String> notes = new ArrayList<>();
            for (String n : List.of(r.failure(), r.quality().isEmpty() ? "" : "quality: " + r.quality(), r.problem(),
                    r.unboxed() ? UNBOXED : ""))
                if (!n.isEmpty()) notes.add(StudentRow.shortened(n));
            s.append("| ").append(String.join(" | ", cell(r.file()), cell(r.student()), cell(r.id()), cell(r.builder()),
                    r.verdict() + (scores.isEmpty() ? "" : " | " + score(r)), num(r.meanRatio(0)),
                    num(r.meanRatio(1)), r.ratios().isEmpty() ? "" : String.format(Locale.ROOT, "%.0f", r.buildMs()),
                    cell(String.join("; ", notes)))).append(" |\n");
        }
        s.append("\nCost ratios: the student's expected cost over the built-in's, geometric mean over the course scenes "
                + "(below 1: cheaper). Per scene in the CSV.\n");
        if (!rosterLines.isEmpty()) s.append("\n## Roster\n\n");
        for (String line : rosterLines) s.append("- ").append(cell(line)).append('\n');
        return s.toString();
    }

    private static String num(double v) {
        return Double.isNaN(v) ? "" : String.format(Locale.ROOT, "%.2f", v);
    }

    private static String cell(String v) {
        return v.replace("|", "\\|").replace("\n", " ");
    }

    private static String quote(String v) {
        return '"' + v.replace("\"", "\"\"").replace("\n", " ") + '"';
    }
}
