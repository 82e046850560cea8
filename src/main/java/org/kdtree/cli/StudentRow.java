package org.kdtree.cli;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.kdtree.files.CsvFields;

/**
 * One student's line of {@code grade-class}'s table: read from the CSV report made of the student's
 * builds (outside the box: {@link StudentJvm}), or, where there is none, the reason why.
 *
 * @param file        the jar's file name
 * @param student     the student's name: the roster's, else the jar's manifest's (see {@link StudentJvm#student}), else the file's
 * @param id          the student's id from the roster, or ""
 * @param builder     the builder's name, or "" if none was graded
 * @param verdict     FAIL, CORRECT or GOOD
 * @param failure     the first contract failure, one line, or ""
 * @param quality     the quality checks failed, or ""
 * @param ratios      per course scene, the student's expected cost over the median plane's and over the SAH's
 * @param buildMs     the student's builds of the course scenes, in all
 * @param problem     "hung ...", "crashed: ..." or "not graded: ...", or ""
 * @param seconds     how long the student's JVM ran
 * @param box         what the student's JVM ran in: "bubblewrap", or "none (--no-sandbox)"
 */
record StudentRow(String file, String student, String id, String builder, String verdict, String failure, String quality,
                  Map<String, double[]> ratios, double buildMs, String problem, double seconds, String box) {
    private static final int LONGEST = 200;

    /** A row for a jar that was not graded to the end: {@code problem} says why. */
    static StudentRow failed(String file, String student, String problem, double seconds, String box) {
        return new StudentRow(file, student, "", "", "FAIL", "", "", Map.of(), 0, problem, seconds, box);
    }

    /** This row with {@code note} added to its problem column. */
    StudentRow withNote(String note) {
        return new StudentRow(file, student, id, builder, verdict, failure, quality, ratios, buildMs,
                problem.isEmpty() ? note : problem + "; " + note, seconds, box);
    }

    /** This row naming the student as the roster does. */
    StudentRow named(String name, String studentId) {
        return new StudentRow(file, name, studentId, builder, verdict, failure, quality, ratios, buildMs, problem, seconds, box);
    }

    /** Whether the student's JVM ran without a box ({@code --no-sandbox}). */
    boolean unboxed() {
        return box.startsWith("none");
    }

    /** The row of a finished grade, from its CSV report ({@link Report#csv}). */
    static StudentRow parse(String file, String student, String csv, double seconds, String box) {
        String builder = "", verdict = "", failure = "", problem = "";
        List<String> quality = new ArrayList<>();
        List<List<String>> scenes = new ArrayList<>();
        for (String line : csv.split("\\R")) {
            List<String> f = CsvFields.of(line);
            if (f.size() < 8 || f.get(0).equals("section")) continue;
            String result = f.get(3);
            switch (f.get(0)) {
                case "contract" -> {
                    if (failure.isEmpty() && result.startsWith("FAIL")) failure = oneLine(result.substring(4).replaceFirst("^: ", ""));
                    if (problem.isEmpty() && result.startsWith("not run")) problem = oneLine(result.substring(7).replaceFirst("^: ", ""));
                }
                case "quality" -> { if (result.startsWith("FAIL")) quality.add(f.get(1)); }
                case "scene" -> scenes.add(f);
                case "verdict" -> { builder = f.get(2); verdict = result.split(":", 2)[0].strip(); }
                default -> { }
            }
        }
        return new StudentRow(file, student, "", builder, verdict.isEmpty() ? "FAIL" : verdict, failure, String.join("; ", quality),
                ratios(scenes), ownMs(scenes), problem, seconds, box);
    }

    /** Each scene's rows are the student's, then the built-ins' in {@link GradeCommand#BUILT_INS} order. */
    private static Map<String, double[]> ratios(List<List<String>> scenes) {
        Map<String, double[]> r = new LinkedHashMap<>();
        int per = GradeCommand.BUILT_INS.size() + 1;
        for (int i = 0; i + per <= scenes.size(); i += per) {
            double own = cost(scenes.get(i));
            r.put(scenes.get(i).get(1), new double[] {own / cost(scenes.get(i + 1 + GradeCommand.BUILT_INS.indexOf("median-plane"))),
                    own / cost(scenes.get(i + 1 + GradeCommand.BUILT_INS.indexOf("sah")))});
        }
        return r;
    }

    private static double ownMs(List<List<String>> scenes) {
        double ms = 0;
        for (int i = 0; i < scenes.size(); i += GradeCommand.BUILT_INS.size() + 1) ms += Double.parseDouble(scenes.get(i).get(7));
        return ms;
    }

    private static double cost(List<String> row) {
        return Double.parseDouble(row.get(4));
    }

    /** The geometric mean of one ratio ({@code which}: 0 median plane, 1 SAH) over the scenes, or NaN if none. */
    double meanRatio(int which) {
        if (ratios.isEmpty()) return Double.NaN;
        double log = 0;
        for (double[] r : ratios.values()) log += Math.log(r[which]);
        return Math.exp(log / ratios.size());
    }

    /** The first line, whole: the CSV keeps it all (a spreadsheet's cell takes it), the Markdown table {@link #shortened} it. */
    static String oneLine(String s) {
        return s.strip().split("\\R", 2)[0];
    }

    /** At most {@value #LONGEST} characters, for a table read on a screen. */
    static String shortened(String line) {
        return line.length() <= LONGEST ? line : line.substring(0, LONGEST - 3) + "...";
    }
}
