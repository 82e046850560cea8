package org.kdtree.cli;

import java.util.List;
import java.util.Locale;

/**
 * Grades as JUnit XML, which GitLab, Jenkins and most CI show: one {@code <testsuite>} per
 * student, one {@code <testcase>} per check of the rubric (classname {@code student/file}), a
 * {@code <failure>} for each check that lost points, its message the student's fault.
 */
final class JunitXml {
    private JunitXml() {
    }

    /** {@return the XML of {@code cards}, one test suite each} */
    static String of(List<Scorecard> cards) {
        int tests = 0, failures = 0;
        double seconds = 0;
        for (Scorecard c : cards) {
            tests += c.checks().size();
            failures += failures(c);
            seconds += c.row().seconds();
        }
        StringBuilder s = new StringBuilder("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
        s.append(String.format(Locale.ROOT, "<testsuites name=\"kdtree grade\" tests=\"%d\" failures=\"%d\" errors=\"0\" time=\"%.3f\">%n",
                tests, failures, seconds));
        for (Scorecard c : cards) suite(s, c);
        return s.append("</testsuites>\n").toString();
    }

    private static int failures(Scorecard c) {
        return (int) c.checks().stream().filter(k -> !k.passed()).count();
    }

    private static void suite(StringBuilder s, Scorecard c) {
        StudentRow r = c.row();
        String classname = r.student() + "/" + r.file();
        s.append(String.format(Locale.ROOT, "  <testsuite name=\"%s\" tests=\"%d\" failures=\"%d\" errors=\"0\" skipped=\"0\" time=\"%.3f\">%n",
                attr(classname), c.checks().size(), failures(c), r.seconds()));
        s.append("    <properties>\n");
        for (String[] p : new String[][] {{"file", r.file()}, {"student", r.student()}, {"id", r.id()}, {"builder", r.builder()},
                {"verdict", r.verdict()}, {"score", Scorecard.points(c.score())}, {"max_score", Scorecard.points(c.maxScore())},
                {"problem", r.problem()}})
            s.append("      <property name=\"").append(p[0]).append("\" value=\"").append(attr(p[1])).append("\"/>\n");
        s.append("    </properties>\n");
        for (Scorecard.Scored k : c.checks()) {
            s.append("    <testcase classname=\"").append(attr(classname)).append("\" name=\"").append(attr(k.check())).append("\" time=\"0\"");
            if (k.passed()) {
                s.append("/>\n");
                continue;
            }
            s.append(">\n      <failure message=\"").append(attr(StudentRow.shortened(StudentRow.oneLine(k.output()))))
                    .append("\" type=\"").append(k.output().startsWith("not graded") ? "not graded" : k.output().startsWith("not") ? "not run" : "fault")
                    .append("\">").append(text(k.output() + "\n" + Scorecard.points(k.score()) + " of " + Scorecard.points(k.max()) + " points"))
                    .append("</failure>\n    </testcase>\n");
        }
        s.append("  </testsuite>\n");
    }

    /** Text fit for an attribute: the five XML escapes, line breaks as spaces, no control characters (XML 1.0 forbids them). */
    private static String attr(String v) {
        return text(v).replace("\"", "&quot;").replace("\n", " ").replace("\r", " ").replace("\t", " ");
    }

    private static String text(String v) {
        StringBuilder s = new StringBuilder(v.length());
        for (int i = 0; i < v.length(); i++) {
            char ch = v.charAt(i);
            switch (ch) {
                case '&' -> s.append("&amp;");
                case '<' -> s.append("&lt;");
                case '>' -> s.append("&gt;");
                default -> s.append(ch < 0x20 && ch != '\n' && ch != '\r' && ch != '\t' || ch == 0xFFFE || ch == 0xFFFF ? '?' : ch);
            }
        }
        return s.toString();
    }
}
