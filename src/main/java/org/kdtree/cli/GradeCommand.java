package org.kdtree.cli;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.kdtree.check.Contract;
import org.kdtree.check.ContractCase;
import org.kdtree.check.ContractViolation;
import org.kdtree.check.CourseScenes;
import org.kdtree.check.QualityChecks;
import org.kdtree.files.AtomicFile;
import org.kdtree.kdtree.BuilderFault;
import org.kdtree.kdtree.KdTree;
import org.kdtree.kdtree.KdTreeBuilder;
import org.kdtree.limits.Deadlines;
import org.kdtree.spec.BuilderSpec;
import org.kdtree.spec.Builders;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/**
 * {@code grade --builder NAME}: a teacher's one command. Runs the builder contract, then builds
 * the course scenes with the student's builder and the three built-ins, runs the quality tier on
 * the student's trees, and prints a table and a verdict (Markdown or CSV with {@code -o}).
 */
@Command(name = "grade", mixinStandardHelpOptions = true,
        description = {"Grade a builder: the contract's checks, the quality tier, and its trees of the course scenes "
                + "against the median plane, object median and SAH (expected cost, nodes, depth, build time).",
                "Every builder runs under supervision: a call that does not return within --call-deadline is stopped "
                        + "and reported as hung, a build past --build-deadline as slow, and the checks after it are not run.",
                "Exit code 0 if it honours the contract, 1 if not."})
final class GradeCommand implements Callable<Integer> {
    /** The built-ins a student's builder is measured against. */
    static final List<String> BUILT_INS = List.of("median-plane", "object-median", "sah");

    @Mixin
    BuilderOptions options = BuilderOptions.kdTrees(null, "the one to grade: a jar on the class path, or --plugin my.jar; "
            + "the settings given are its, the built-ins keep their defaults");

    /** The graded builder, with the settings given. */
    private BuilderSpec graded;

    /** {@code grade-class}'s child: the one student's jar, whose one builder is graded (no other jar is loaded). */
    @Option(names = "--student-jar", hidden = true, paramLabel = "JAR")
    Path studentJar;

    @Option(names = {"-o", "--output"}, paramLabel = "FILE", description = "Also write the report: .md (Markdown) or .csv.")
    Path output;

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

    /** Why the remaining checks are not run (a hung or slow builder, said once), or null while they are. */
    private String stopped;

    @Override public Integer call() throws IOException {
        String builder = studentJar != null ? onlyBuilder(studentJar) : options.builder();
        if (builder == null) throw new IllegalArgumentException("grade needs --builder NAME (a folder of students' jars: grade-class FOLDER)");
        graded = options.spec(builder);
        graded.create(); // an unknown name, or a setting it does not take, fails here in one line
        if (output != null) {
            String n = output.getFileName().toString().toLowerCase(Locale.ROOT);
            if (!n.endsWith(".md") && !n.endsWith(".csv"))
                throw new IllegalArgumentException("-o " + output + ": write a .md (Markdown) or .csv report");
            CommandFiles.requireWritable("-o", output);
        }
        List<ContractCase> cases = new ArrayList<>(Contract.cases());
        cases.addAll(Contract.randomCases());
        List<Check> contract = new ArrayList<>(), quality = new ArrayList<>();
        List<Row> rows = new ArrayList<>();
        try (ProgressBar bar = progress.bar(cases.size() + CourseScenes.all().size(), "checks")) {
            Contract.withDeadlines(deadlines.deadlines(Deadlines.GRADE), () -> {
                for (int i = 0; i < cases.size(); i++) {
                    bar.step(i, cases.get(i).name());
                    contract.add(run(cases.get(i)));
                }
                if (contract.stream().allMatch(Check::passed)) compare(quality, rows, bar, cases.size());
            });
        }
        boolean correct = contract.stream().allMatch(Check::passed);
        String verdict = verdict(contract, quality, rows);
        Report report = new Report(builder, contract, quality, rows, verdict);
        System.out.print(report.text());
        if (output != null) {
            AtomicFile.writeString(output, output.toString().toLowerCase(Locale.ROOT).endsWith(".csv") ? report.csv() : report.markdown());
            System.out.println("report: " + output);
        }
        return correct ? 0 : 1;
    }

    /** The name of the one builder a student's jar lists; a jar with none or several is refused in one line. */
    private static String onlyBuilder(Path jar) {
        List<String> names = Builders.loadPlugins(jar);
        if (names.size() != 1)
            throw new IllegalArgumentException(jar.getFileName() + " lists " + names.size() + " builders (" + String.join(", ", names)
                    + "); a student's jar lists one");
        return names.get(0);
    }

    /** Runs one case, unless the builder already hung or was too slow: then it is listed as not run, pointing at that finding. */
    private Check run(ContractCase c) {
        if (stopped != null) return new Check(c.name(), null, stopped);
        try {
            c.run(graded::create);
            return new Check(c.name(), null, null);
        } catch (AssertionError | RuntimeException e) {
            noteIfHaltedBy(e, c.name());
            String failure = e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage();
            String first = firstFailures.putIfAbsent(failure, c.name());
            return new Check(c.name(), first == null ? failure : "the same failure as " + first + " above", null);
        }
    }

    /**
     * Each failure's message and the check that reported it first: the checks of scenes above 50
     * primitives first build 50 random shapes (to catch a builder that never stops before a big
     * scene), so one fault there fails them all with the same message, said once.
     */
    private final java.util.Map<String, String> firstFailures = new java.util.HashMap<>();

    /** A builder that hung or was too slow would only do so again: the remaining checks are not run. */
    private void noteIfHaltedBy(Throwable e, String where) {
        for (Throwable t = e; t != null; t = t.getCause()) {
            if (t instanceof BuilderFault f && f.kind() == BuilderFault.Kind.HUNG)
                stopped = "builder " + f.builder() + " hung in " + f.method() + " (see " + where + ")";
            else if (t instanceof BuilderFault f && f.kind() == BuilderFault.Kind.SLOW)
                stopped = "builder " + f.builder() + " is too slow (see " + where + ")";
        }
    }

    /** Builds every course scene with the student's builder and the built-ins; the quality tier on the student's trees. */
    private void compare(List<Check> quality, List<Row> rows, ProgressBar bar, int stepsBefore) {
        String[] failures = new String[QualityChecks.NAMES.size()];
        List<CourseScenes.Named> scenes = CourseScenes.all();
        for (int s = 0; s < scenes.size(); s++) {
            CourseScenes.Named scene = scenes.get(s);
            bar.step(stepsBefore + s, scene.name());
            KdTreeBuilder own = graded.create();
            KdTree ownTree;
            try {
                ownTree = timed(own, scene, rows);
            } catch (ContractViolation v) { // it hung, was slow or threw on a course scene: no quality to measure
                noteIfHaltedBy(v, "builds every course scene");
                quality.add(new Check("builds every course scene", v.getMessage(), null));
                return;
            }
            KdTree median = null;
            for (String b : BUILT_INS) {
                KdTree t = timed(Builders.create(b), scene, rows);
                if (b.equals("median-plane")) median = t;
            }
            List<String> found = QualityChecks.check(own, scene, ownTree, median.stats().expectedCost());
            for (int i = 0; i < failures.length; i++) if (failures[i] == null) failures[i] = found.get(i);
        }
        for (int i = 0; i < failures.length; i++) quality.add(new Check(QualityChecks.NAMES.get(i), failures[i], null));
    }

    private static KdTree timed(KdTreeBuilder b, CourseScenes.Named scene, List<Row> rows) {
        long t0 = System.nanoTime();
        KdTree t = Contract.build(b, scene.primitives(), scene.name());
        double ms = (System.nanoTime() - t0) / 1e6;
        rows.add(new Row(scene.name(), b.name(), t.stats().expectedCost(), t.nodeCount(), t.stats().maxDepth(), ms));
        return t;
    }

    /** FAIL if it breaks the contract; CORRECT if it honours it but fails a quality check; GOOD if neither. */
    static String verdict(List<Check> contract, List<Check> quality, List<Row> rows) {
        List<String> broken = contract.stream().filter(c -> c.failure() != null).map(Check::name).toList();
        long notRun = contract.stream().filter(c -> c.notRun() != null).count();
        if (!broken.isEmpty())
            return "FAIL: breaks the contract (" + broken.size() + " of " + contract.size() + " checks: "
                    + String.join(", ", broken) + ")" + (notRun == 0 ? "" : "; " + notRun + " not run: "
                    + contract.get(contract.size() - 1).notRun());
        List<String> weak = quality.stream().filter(c -> !c.passed()).map(Check::name).toList();
        StringBuilder v = new StringBuilder(weak.isEmpty() ? "GOOD" : "CORRECT");
        v.append(": honours the contract (").append(contract.size()).append(" of ").append(contract.size()).append(" checks); ");
        v.append(weak.isEmpty() ? "passes every quality check" : "fails quality: " + String.join(", ", weak));
        for (String b : BUILT_INS) v.append("; cheaper than ").append(b).append(" on ").append(cheaper(rows, b));
        return v.toString();
    }

    /** "k of n scenes": where the student's tree has a lower expected cost than built-in {@code b}'s. */
    private static String cheaper(List<Row> rows, String b) {
        int n = 0, k = 0;
        for (int i = 0; i < rows.size(); i += BUILT_INS.size() + 1) {
            Row own = rows.get(i);
            Row other = rows.get(i + 1 + BUILT_INS.indexOf(b));
            n++;
            if (own.cost() < other.cost()) k++;
        }
        return k + " of " + n + " scenes";
    }
}
