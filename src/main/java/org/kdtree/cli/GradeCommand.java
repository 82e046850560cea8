package org.kdtree.cli;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.kdtree.check.Contract;
import org.kdtree.check.CourseScenes;
import org.kdtree.check.TreeTape;
import org.kdtree.files.AtomicFile;
import org.kdtree.limits.Deadlines;
import org.kdtree.limits.Limits;
import org.kdtree.spec.BuilderSpec;
import org.kdtree.spec.Builders;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/**
 * {@code grade --builder NAME}: a teacher's one command. Runs the builder contract, then builds
 * the course scenes with the student's builder and the three built-ins, runs the quality tier on
 * the student's trees, and prints a table and a verdict (Markdown or CSV with {@code -o}).
 * {@code grade --student-jar JAR}: the same of a student's jar, run as {@code grade-class} runs
 * each (in a JVM of its own in a box, the grade made here from the trees it sends).
 */
@Command(name = "grade", mixinStandardHelpOptions = true,
        description = {"Grade a builder: the contract's checks, the quality tier, and its trees of the course scenes "
                + "against the median plane, object median and SAH (expected cost, nodes, depth, build time).",
                "Every builder runs under supervision: a call that does not return within --call-deadline is stopped "
                        + "and reported as hung, a build past --build-deadline as slow, and the checks after it are not run.",
                "With --student-jar, the student's builder runs as grade-class runs each: in a JVM of its own in a box.",
                "Exit code 0 if it honours the contract, 1 if not."})
final class GradeCommand implements Callable<Integer> {
    /** The built-ins a student's builder is measured against. */
    static final List<String> BUILT_INS = List.of("median-plane", "object-median", "sah");

    @Mixin
    BuilderOptions options = BuilderOptions.kdTrees(null, "the one to grade: a jar on the class path, or --plugin my.jar; "
            + "the settings given are its, the built-ins keep their defaults");

    /** The graded builder, with the settings given. */
    private BuilderSpec graded;

    /** A student's jar, whose one builder is graded in a JVM of its own, in a box; the grade is made here (as grade-class does). */
    @Option(names = "--student-jar", paramLabel = "JAR", description = "A student's jar: its one builder graded as grade-class grades "
            + "each jar: in a JVM of its own, in a box (bubblewrap), the grade made outside it from the trees it sends.")
    Path studentJar;

    @Option(names = "--no-sandbox", description = "With --student-jar: run the student's JVM without a box (where bubblewrap cannot run).")
    boolean noSandbox;

    @Option(names = {"-o", "--output"}, paramLabel = "FILE", description = "Also write the report: .md (Markdown) or .csv; "
            + "with --format gradescope, Gradescope's results.json.")
    Path output;

    @Option(names = "--format", paramLabel = "FORMAT", defaultValue = "report",
            description = "What -o writes: report (Markdown or CSV, by the file's name; the default) or gradescope (Gradescope's "
                    + "results.json, with --student-jar: one test per check, scored by --rubric).")
    String format;

    @Mixin
    ScoringOptions scoring;

    @Mixin
    ProgressOption progress;

    @Mixin
    DeadlineOptions deadlines;

    /**
     * One checked item: a contract case or a quality check. It passed if neither {@code failure}
     * (what failed) nor {@code notRun} (the finding it was skipped after: a hung or slow builder) is set.
     */
    record Check(String name, String failure, String notRun) {
        boolean passed() { return failure == null && notRun == null; }
    }

    /** One tree of one course scene. */
    record Row(String scene, String builder, double cost, int nodes, int depth, double ms) {
    }

    @Override public Integer call() throws IOException {
        if (!List.of("report", "gradescope").contains(format))
            throw new IllegalArgumentException("--format " + format + ": give report (Markdown or CSV) or gradescope (results.json)");
        if (gradescope() && studentJar == null)
            throw new IllegalArgumentException("--format gradescope grades a student's jar as Gradescope's autograder does: give --student-jar JAR");
        if (gradescope() && output == null) throw new IllegalArgumentException("--format gradescope needs -o FILE (results.json)");
        if (studentJar != null) return boxed();
        String builder = options.builder();
        if (builder == null) throw new IllegalArgumentException("grade needs --builder NAME or --student-jar JAR (a folder of students' jars: grade-class FOLDER)");
        graded = options.spec(builder);
        graded.create(); // an unknown name, or a setting it does not take, fails here in one line
        Rubric points = checkOutputs();
        long t0 = System.nanoTime();
        Report report;
        try (ProgressBar bar = progress.bar(steps(), "checks")) {
            report = new GradeRun(graded::create, null).run(builder, deadlines.deadlines(Deadlines.GRADE), bar);
        }
        StudentRow row = StudentRow.parse(builder, builder, report.csv(), (System.nanoTime() - t0) / 1e9, "none (in this JVM)");
        write(report, row, points);
        return report.contract().stream().allMatch(Check::passed) ? 0 : 1;
    }

    private boolean gradescope() {
        return format.equals("gradescope");
    }

    /** Refuses, before any work, a file that cannot be written or a rubric that cannot be read; {@return the rubric, or null} */
    private Rubric checkOutputs() {
        if (output != null) requireReportName();
        if (scoring.junitXml != null) CommandFiles.requireWritable("--junit-xml", scoring.junitXml);
        for (Path out : java.util.Arrays.asList(output, scoring.junitXml)) {
            CommandFiles.requireNotInput(out == output ? "-o" : "--junit-xml", out, "--rubric", scoring.rubric);
            CommandFiles.requireNotInput(out == output ? "-o" : "--junit-xml", out, "--student-jar", studentJar);
        }
        return scoring.read();
    }

    /** Prints the report (and the score, with a rubric) and writes the files asked for; {@code report} null if the jar was not graded. */
    private void write(Report report, StudentRow row, Rubric points) throws IOException {
        Scorecard card = Scorecard.of(ScoringOptions.orOnePointEach(points), row, report);
        if (report != null) System.out.print(report.text());
        if (report != null && studentJar != null && !row.problem().isEmpty()) System.out.println("the student's JVM: " + row.problem());
        if (report != null && studentJar != null && row.unboxed()) System.out.println(ClassTable.UNBOXED);
        if (report != null && points != null) System.out.print(card.text());
        if (output != null && (report != null || gradescope())) {   // a jar not graded has no report to write, but a score of 0
            String name = output.toString().toLowerCase(Locale.ROOT);
            AtomicFile.writeString(output, gradescope() ? GradescopeResults.of(card, report)
                    : name.endsWith(".csv") ? report.csv() : report.markdown() + (points == null ? "" : "\n## Score\n\n```" + card.text() + "```\n"));
            System.out.println((gradescope() ? "Gradescope results: " : "report: ") + output);
        }
        if (scoring.junitXml != null) {
            AtomicFile.writeString(scoring.junitXml, JunitXml.of(List.of(card)));
            System.out.println("JUnit XML: " + scoring.junitXml);
        }
    }

    /**
     * A teacher's grade of one student's jar: run as grade-class runs each, in a JVM of its own in a
     * box, the report made here; a jar not graded to the end is one line (exit 2 if it is no
     * student's jar, 4 if its JVM crashed or was killed).
     */
    private int boxed() throws IOException {
        if (!Files.isRegularFile(studentJar)) throw new IllegalArgumentException("--student-jar " + studentJar + ": no such file");
        Rubric points = checkOutputs();
        StudentJvm jvm = new StudentJvm(deadlines.deadlines(Deadlines.GRADE), Limits.STUDENT_SECONDS, Limits.STUDENT_HEAP_MB,
                ClassGradeCommand.box(noSandbox, "grade --student-jar")).withReference();
        StudentJvm.Graded g = jvm.run(studentJar);
        StudentRow row = g.row();
        if (g.report() == null) {
            if (gradescope() || scoring.junitXml != null) write(null, row, points); // the student's score is 0, and says why
            System.err.println("error: grade " + studentJar.getFileName() + ": " + row.problem());
            return row.problem().startsWith("not graded") ? Failure.USAGE : Failure.BUILDER;
        }
        write(g.report(), row, points);
        return g.report().contract().stream().allMatch(Check::passed) ? 0 : 1;
    }

    private void requireReportName() {
        String n = output.getFileName().toString().toLowerCase(Locale.ROOT);
        if (!gradescope() && !n.endsWith(".md") && !n.endsWith(".csv"))   // Gradescope's file is JSON whatever its name
            throw new IllegalArgumentException("-o " + output + ": write a .md (Markdown) or .csv report");
        CommandFiles.requireWritable("-o", output);
    }

    /** The checks and the course scenes: the progress bar's steps. */
    static int steps() {
        return Contract.cases().size() + Contract.randomCases().size() + CourseScenes.all().size();
    }
}
