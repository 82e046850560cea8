package org.kdtree.cli;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.function.ToDoubleFunction;

/**
 * One student's grade scored by a {@link Rubric}: each check's points and what the student reads
 * about it. Made from the report the grading JVM made of the student's trees (never from anything
 * the student's JVM said of itself, but the build times, which say so); a jar not graded to the
 * end scores nothing, each check saying why.
 *
 * @param row    the student's row of the class table
 * @param checks every check of the rubric, in its order
 */
record Scorecard(StudentRow row, List<Scored> checks) {
    /**
     * One check, scored.
     *
     * @param check      its name
     * @param score      the points earned
     * @param max        the points it is worth
     * @param passed     whether it passed (a measured check: whether it earned all its points)
     * @param output     what the student reads: the fault, named as the builder's, or the figure
     * @param visibility when the student sees it (Gradescope's word)
     */
    record Scored(String check, double score, double max, boolean passed, String output, String visibility) {
    }

    /** {@return the points earned in all} */
    double score() {
        return Rubric.round(checks.stream().mapToDouble(Scored::score).sum());
    }

    /** {@return the most points there were} */
    double maxScore() {
        return Rubric.round(checks.stream().mapToDouble(Scored::max).sum());
    }

    /**
     * Scores one student's grade.
     *
     * @param rubric the points per check
     * @param row    the student's row (its problem says why a jar was not graded to the end)
     * @param report the grade made of the student's trees, or null if there is none
     * @return the scorecard
     */
    static Scorecard of(Rubric rubric, StudentRow row, Report report) {
        List<Scored> out = new ArrayList<>();
        for (Rubric.Item item : rubric.items()) {
            if (report == null) {
                out.add(new Scored(item.check(), 0, item.points(), false, notGraded(row), item.visibility()));
                continue;
            }
            out.add(item.measured() ? measured(item, report) : passFail(item, report));
        }
        return new Scorecard(row, out);
    }

    private static String notGraded(StudentRow row) {
        String p = row.problem().isEmpty() ? "the submission was not graded" : row.problem();
        return "not graded: " + p.replaceFirst("^not graded: ", "");
    }

    private static Scored passFail(Rubric.Item item, Report report) {
        GradeCommand.Check c = find(report.contract(), item.check());
        if (c == null) c = find(report.quality(), item.check());
        String output;
        if (c == null) output = "not run: " + whyNoQuality(report);
        else if (c.notRun() != null) output = "not run: " + c.notRun();
        else if (c.failure() != null) output = "FAIL, your builder's fault: " + c.failure();
        else output = "pass";
        boolean passed = c != null && c.passed();
        return new Scored(item.check(), passed ? item.points() : 0, item.points(), passed, output, item.visibility());
    }

    /** Why the quality tier was not run: the contract broken, or the builder failed on a course scene. */
    private static String whyNoQuality(Report report) {
        GradeCommand.Check scenes = find(report.quality(), "builds every course scene");
        if (scenes != null && scenes.failure() != null) return "your builder failed on a course scene: " + scenes.failure();
        return "the quality tier is run only on a builder that honours the contract";
    }

    private static Scored measured(Rubric.Item item, Report report) {
        boolean cost = item.check().equals(Rubric.COST);
        double ratio = cost ? costRatio(report.rows()) : timeRatio(report.rows());
        if (Double.isNaN(ratio))
            return new Scored(item.check(), 0, item.points(), item.points() == 0, "not measured: " + whyNoQuality(report), item.visibility());
        double earned = item.earned(ratio);
        String output = String.format(Locale.ROOT, "%s %.2f times the library's SAH's (geometric mean over the course scenes); "
                        + "all %s points at %.2f or less, none at %.2f or more: %s of %s",
                cost ? "your trees' expected cost is" : "your builds took", ratio, points(item.points()), item.fullAt(), item.zeroAt(),
                points(earned), points(item.points()));
        if (!cost) output += "; build times are measured inside your JVM, not checked by the grader";
        return new Scored(item.check(), earned, item.points(), earned >= item.points(), output, item.visibility());
    }

    /** {@return the student's expected cost over the SAH's, geometric mean over the course scenes, NaN if not built} */
    static double costRatio(List<GradeCommand.Row> rows) {
        return meanRatio(rows, GradeCommand.Row::cost);
    }

    /** {@return the student's build time over the SAH's, geometric mean over the course scenes, NaN if not built} */
    static double timeRatio(List<GradeCommand.Row> rows) {
        return meanRatio(rows, r -> Math.max(r.ms(), 0.001));   // a build under the timer's grain is not free
    }

    /** Each course scene's rows are the student's, then the built-ins' in {@link GradeCommand#BUILT_INS} order. */
    private static double meanRatio(List<GradeCommand.Row> rows, ToDoubleFunction<GradeCommand.Row> f) {
        int per = GradeCommand.BUILT_INS.size() + 1, sah = 1 + GradeCommand.BUILT_INS.indexOf("sah");
        double log = 0;
        int n = 0;
        for (int i = 0; i + per <= rows.size(); i += per, n++) log += Math.log(f.applyAsDouble(rows.get(i)) / f.applyAsDouble(rows.get(i + sah)));
        return n == 0 ? Double.NaN : Math.exp(log / n);
    }

    private static GradeCommand.Check find(List<GradeCommand.Check> checks, String name) {
        for (GradeCommand.Check c : checks) if (c.name().equals(name)) return c;
        return null;
    }

    /** Points as a teacher writes them: 3, 2.5, 0.67. */
    static String points(double p) {
        return p == Math.rint(p) ? Long.toString((long) p) : String.format(Locale.ROOT, "%.2f", p).replaceFirst("0$", "");
    }

    /** {@return the score as one line: "score: 31.5 of 40 points"} */
    String line() {
        return "score: " + points(score()) + " of " + points(maxScore()) + " points";
    }

    /** {@return each check's points, one line each, for the console and Markdown} */
    String text() {
        StringBuilder s = new StringBuilder("\nscore by the rubric\n");
        for (Scored c : checks)
            s.append(String.format(Locale.ROOT, "  %-44s %6s of %-6s %s%n", c.check(), points(c.score()), points(c.max()), c.visibility()));
        return s.append(line()).append('\n').toString();
    }
}
