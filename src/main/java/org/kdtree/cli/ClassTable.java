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

    /** @param scenes the course scenes' names, the CSV's per-scene columns */
    ClassTable(List<StudentRow> rows, List<String> scenes) {
        this.rows = new ArrayList<>(rows);
        this.rows.sort(Comparator.comparingInt((StudentRow r) -> ORDER.indexOf(r.verdict())).thenComparing(StudentRow::file));
        this.scenes = scenes;
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
        StringBuilder s = new StringBuilder("file,student,builder,verdict,first_failure,quality_failed,problem,"
                + "cost_vs_median,cost_vs_sah,build_ms,seconds,box");
        for (String scene : scenes) s.append(',').append(quote("vs_median " + scene)).append(',').append(quote("vs_sah " + scene));
        s.append('\n');
        for (StudentRow r : rows) {
            s.append(String.join(",", quote(r.file()), quote(r.student()), quote(r.builder()), r.verdict(), quote(r.failure()),
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
        StringBuilder s = new StringBuilder("# Class grades\n\n**" + summary() + "**\n\n"
                + "| file | student | builder | verdict | cost vs median | cost vs SAH | build ms | first failure, quality failed, problem |\n"
                + "| --- | --- | --- | --- | ---: | ---: | ---: | --- |\n");
        for (StudentRow r : rows) {
            List<String> notes = new ArrayList<>();
            for (String n : List.of(r.failure(), r.quality().isEmpty() ? "" : "quality: " + r.quality(), r.problem(),
                    r.unboxed() ? UNBOXED : ""))
                if (!n.isEmpty()) notes.add(StudentRow.shortened(n));
            s.append("| ").append(String.join(" | ", cell(r.file()), cell(r.student()), cell(r.builder()), r.verdict(), num(r.meanRatio(0)),
                    num(r.meanRatio(1)), r.ratios().isEmpty() ? "" : String.format(Locale.ROOT, "%.0f", r.buildMs()),
                    cell(String.join("; ", notes)))).append(" |\n");
        }
        return s.append("\nCost ratios: the student's expected cost over the built-in's, geometric mean over the course scenes "
                + "(below 1: cheaper). Per scene in the CSV.\n").toString();
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
