package org.kdtree.cli;

import java.util.List;
import java.util.Locale;

/** The grading report of {@code grade}, as the console's text, Markdown or CSV: one content, three layouts. */
record Report(String builder, List<GradeCommand.Check> contract, List<GradeCommand.Check> quality,
              List<GradeCommand.Row> rows, String verdict) {

    String text() {
        StringBuilder s = new StringBuilder("grade: builder " + builder + "\n\ncontract\n");
        for (GradeCommand.Check c : contract) s.append(line(c));
        if (!quality.isEmpty()) {
            s.append("\nquality (course scenes)\n");
            for (GradeCommand.Check c : quality) s.append(line(c));
        }
        if (!rows.isEmpty()) {
            s.append(String.format(Locale.ROOT, "%n%-20s %-18s %12s %9s %6s %10s %9s%n", "scene", "builder", "expected cost",
                    "nodes", "depth", "build ms", "yours/it"));
            double own = 0;
            for (int i = 0; i < rows.size(); i++) {
                GradeCommand.Row r = rows.get(i);
                boolean yours = i % (GradeCommand.BUILT_INS.size() + 1) == 0; // each scene: yours, then the built-ins
                if (yours) own = r.cost();
                s.append(String.format(Locale.ROOT, "%-20s %-18s %12.2f %9d %6d %10.1f %9s%n", yours ? r.scene() : "", r.builder(),
                        r.cost(), r.nodes(), r.depth(), r.ms(), yours ? "" : String.format(Locale.ROOT, "%.2f", own / r.cost())));
            }
        }
        return s.append("\nverdict: ").append(verdict).append('\n').toString();
    }

    private static String line(GradeCommand.Check c) {
        return String.format(Locale.ROOT, "  %-44s %s%n", c.name(), result(c, "  ", false));
    }

    String markdown() {
        StringBuilder s = new StringBuilder("# Grade: " + builder + "\n\n**Verdict:** " + verdict + "\n\n## Contract\n\n| check | result |\n| --- | --- |\n");
        for (GradeCommand.Check c : contract) s.append(mdRow(c));
        if (!quality.isEmpty()) {
            s.append("\n## Quality (course scenes)\n\n| check | result |\n| --- | --- |\n");
            for (GradeCommand.Check c : quality) s.append(mdRow(c));
        }
        if (!rows.isEmpty()) {
            s.append("\n## Course scenes\n\n| scene | builder | expected cost | nodes | depth | build ms |\n| --- | --- | ---: | ---: | ---: | ---: |\n");
            for (GradeCommand.Row r : rows)
                s.append(String.format(Locale.ROOT, "| %s | %s | %.2f | %d | %d | %.1f |%n", r.scene(), r.builder(), r.cost(), r.nodes(), r.depth(), r.ms()));
        }
        return s.toString();
    }

    private static String mdRow(GradeCommand.Check c) {
        return "| " + c.name() + " | " + result(c, ": ", true).replace("|", "\\|").replace("\n", " ") + " |\n";
    }

    String csv() {
        StringBuilder s = new StringBuilder("section,item,builder,result,expected_cost,nodes,depth,build_ms\n");
        for (GradeCommand.Check c : contract) s.append(csvCheck("contract", c));
        for (GradeCommand.Check c : quality) s.append(csvCheck("quality", c));
        for (GradeCommand.Row r : rows)
            s.append(String.format(Locale.ROOT, "scene,%s,%s,,%.4f,%d,%d,%.2f%n", quote(r.scene()), quote(r.builder()), r.cost(), r.nodes(), r.depth(), r.ms()));
        return s.append("verdict,,").append(quote(builder)).append(',').append(quote(verdict)).append(",,,,\n").toString();
    }

    private String csvCheck(String section, GradeCommand.Check c) {
        return section + "," + quote(c.name()) + "," + quote(builder) + "," + quote(result(c, ": ", true)) + ",,,,\n";
    }

    private static String quote(String v) {
        return '"' + v.replace("\"", "\"\"").replace("\n", " ") + '"';
    }

    /**
     * "pass", "FAIL" and what failed (its first line unless {@code whole}), or "not run" and the
     * finding it was skipped after; {@code gap} after the word.
     */
    private static String result(GradeCommand.Check c, String gap, boolean whole) {
        if (c.notRun() != null) return "not run" + gap + c.notRun();
        return c.failure() == null ? "pass" : "FAIL" + gap + (whole ? c.failure() : firstLine(c.failure()));
    }

    private static String firstLine(String s) {
        int nl = s.indexOf('\n');
        return nl < 0 ? s : s.substring(0, nl).stripTrailing() + " (and more)";
    }
}
