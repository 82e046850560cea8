package org.kdtree.cli;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Supplier;
import org.kdtree.check.Contract;
import org.kdtree.check.ContractCase;
import org.kdtree.check.ContractViolation;
import org.kdtree.check.CourseScenes;
import org.kdtree.check.QualityChecks;
import org.kdtree.check.TreeTape;
import org.kdtree.kdtree.BuilderFault;
import org.kdtree.kdtree.KdTree;
import org.kdtree.kdtree.KdTreeBuilder;
import org.kdtree.limits.Deadlines;
import org.kdtree.spec.Builders;

/**
 * One grade of one builder, as {@code grade} prints it: the contract's cases, then the course
 * scenes built by it and by the built-ins, the quality tier on its trees, the verdict.
 *
 * <p>Run in one of three ways: in place (the builder's code runs here); on the untrusted side of a
 * box, recording its builds into a {@link TreeTape.Recorder} (only the graded builder's builds:
 * the trusted side does the rest); on the trusted side, replaying that tape through a
 * {@link TreeTape.Player}, so that every check and the verdict are made where the builder's code
 * never ran.
 */
final class GradeRun {
    /** The built-ins' rows of each course scene, for replays: the same trees for every student of a class. */
    private static final Map<String, List<GradeCommand.Row>> BUILT_IN_ROWS = new ConcurrentHashMap<>();

    private final Supplier<KdTreeBuilder> create;
    private final TreeTape tape;
    /** The SAH's build times to compare the graded builder's with, by scene, or null for this JVM's own. */
    private final Map<String, Double> sahMillis;
    /** Each failure's message and the check that reported it first (said once: see {@link #run(ContractCase)}). */
    private final Map<String, String> firstFailures = new HashMap<>();
    /** Why the remaining checks are not run (a hung or slow builder, said once), or null while they are. */
    private String stopped;

    /**
     * @param create makes the graded builder (a stand-in of it for a replay)
     * @param tape null to run in place, else the tape the graded builder's builds go into or come from
     */
    GradeRun(Supplier<KdTreeBuilder> create, TreeTape tape) {
        this(create, tape, null);
    }

    /**
     * @param create makes the graded builder (a stand-in of it for a replay)
     * @param tape null to run in place, else the tape the graded builder's builds go into or come from
     * @param sahMillis the SAH's build time on each course scene in a JVM started as the graded builder's, or null for this JVM's own
     */
    GradeRun(Supplier<KdTreeBuilder> create, TreeTape tape, Map<String, Double> sahMillis) {
        this.create = create;
        this.tape = tape;
        this.sahMillis = sahMillis;
    }

    /** Runs every check; on the untrusted side of a box, only up to the graded builder's own trees. */
    Report run(String builder, Deadlines deadlines, ProgressBar bar) {
        List<ContractCase> cases = new ArrayList<>(Contract.cases());
        cases.addAll(Contract.randomCases());
        List<GradeCommand.Check> contract = new ArrayList<>(), quality = new ArrayList<>();
        List<GradeCommand.Row> rows = new ArrayList<>();
        Runnable all = () -> Contract.withDeadlines(deadlines, () -> {
            for (int i = 0; i < cases.size(); i++) {
                bar.step(i, cases.get(i).name());
                contract.add(run(cases.get(i)));
            }
            if (contract.stream().allMatch(GradeCommand.Check::passed)) compare(quality, rows, bar, cases.size());
        });
        if (tape == null) all.run();
        else Contract.withTape(tape, all);
        return new Report(builder, contract, quality, rows, recording() ? "" : verdict(contract, quality, rows)); // the box's side judges nothing
    }

    /** Whether this is the box's side: its builds are recorded, and the rest is the trusted side's. */
    private boolean recording() {
        return tape instanceof TreeTape.Recorder;
    }

    /** Runs one case, unless the builder already hung or was too slow: then it is listed as not run, pointing at that finding. */
    private GradeCommand.Check run(ContractCase c) {
        if (stopped != null) return new GradeCommand.Check(c.name(), null, stopped);
        try {
            c.run(create);
            return new GradeCommand.Check(c.name(), null, null);
        } catch (AssertionError | RuntimeException e) {
            noteIfHaltedBy(e, c.name());
            String failure = e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage();
            // the checks of scenes above 50 primitives first build 50 random shapes (to catch a builder that never
            // stops before a big scene), so one fault there fails them all with the same message: said once
            String first = firstFailures.putIfAbsent(failure, c.name());
            return new GradeCommand.Check(c.name(), first == null ? failure : "the same failure as " + first + " above", null);
        }
    }

    /** A builder that hung or was too slow would only do so again: the remaining checks are not run. */
    private void noteIfHaltedBy(Throwable e, String where) {
        for (Throwable t = e; t != null; t = t.getCause()) {
            if (t instanceof BuilderFault f && f.kind() == BuilderFault.Kind.HUNG)
                stopped = "builder " + f.builder() + " hung in " + f.method() + " (see " + where + ")";
            else if (t instanceof BuilderFault f && f.kind() == BuilderFault.Kind.SLOW)
                stopped = "builder " + f.builder() + " is too slow (see " + where + ")";
        }
    }

    /** Builds every course scene with the graded builder and the built-ins; the quality tier on the graded builder's trees. */
    private void compare(List<GradeCommand.Check> quality, List<GradeCommand.Row> rows, ProgressBar bar, int stepsBefore) {
        String[] failures = new String[QualityChecks.NAMES.size()];
        List<CourseScenes.Named> scenes = CourseScenes.all();
        for (int s = 0; s < scenes.size(); s++) {
            CourseScenes.Named scene = scenes.get(s);
            bar.step(stepsBefore + s, scene.name());
            KdTreeBuilder own = create.get();
            KdTree ownTree;
            try {
                ownTree = timed(own, scene, rows);
            } catch (ContractViolation v) { // it hung, was slow or threw on a course scene: no quality to measure
                noteIfHaltedBy(v, "builds every course scene");
                quality.add(new GradeCommand.Check("builds every course scene", v.getMessage(), null));
                return;
            }
            if (recording()) continue; // the trusted side builds the built-ins and checks the quality
            double median = builtIns(scene, rows);
            List<String> found = QualityChecks.check(own, scene, ownTree, median);
            for (int i = 0; i < failures.length; i++) if (failures[i] == null) failures[i] = found.get(i);
        }
        if (recording()) return;
        for (int i = 0; i < failures.length; i++) quality.add(new GradeCommand.Check(QualityChecks.NAMES.get(i), failures[i], null));
    }

    /** Adds the built-ins' rows of {@code scene} (once per scene for a class's replays); returns the median plane's expected cost. */
    private double builtIns(CourseScenes.Named scene, List<GradeCommand.Row> rows) {
        List<GradeCommand.Row> own = tape == null ? builtInRows(scene) : BUILT_IN_ROWS.computeIfAbsent(scene.name(), k -> builtInRows(scene));
        int sah = GradeCommand.BUILT_INS.indexOf("sah");
        for (int i = 0; i < own.size(); i++) {
            GradeCommand.Row r = own.get(i);
            Double ms = i == sah && sahMillis != null ? sahMillis.get(scene.name()) : null;
            rows.add(ms == null ? r : new GradeCommand.Row(r.scene(), r.builder(), r.cost(), r.nodes(), r.depth(), ms));
        }
        return own.get(GradeCommand.BUILT_INS.indexOf("median-plane")).cost();
    }

    private static List<GradeCommand.Row> builtInRows(CourseScenes.Named scene) {
        List<GradeCommand.Row> rows = new ArrayList<>();
        for (String b : GradeCommand.BUILT_INS) timed(Builders.create(b), scene, rows, null);
        return List.copyOf(rows);
    }

    private KdTree timed(KdTreeBuilder b, CourseScenes.Named scene, List<GradeCommand.Row> rows) {
        return timed(b, scene, rows, tape);
    }

    /** Builds and adds the row; the graded builder's time is the untrusted side's, as its tape says. */
    private static KdTree timed(KdTreeBuilder b, CourseScenes.Named scene, List<GradeCommand.Row> rows, TreeTape tape) {
        long t0 = System.nanoTime();
        KdTree t = Contract.build(b, scene.primitives(), scene.name());
        double ms = tape != null ? tape.lastMillis() : (System.nanoTime() - t0) / 1e6;
        rows.add(new GradeCommand.Row(scene.name(), b.name(), t.stats().expectedCost(), t.nodeCount(), t.stats().maxDepth(), ms));
        return t;
    }

    /** FAIL if it breaks the contract; CORRECT if it honours it but fails a quality check; GOOD if neither. */
    static String verdict(List<GradeCommand.Check> contract, List<GradeCommand.Check> quality, List<GradeCommand.Row> rows) {
        List<String> broken = contract.stream().filter(c -> c.failure() != null).map(GradeCommand.Check::name).toList();
        long notRun = contract.stream().filter(c -> c.notRun() != null).count();
        if (!broken.isEmpty())
            return "FAIL: breaks the contract (" + broken.size() + " of " + contract.size() + " checks: "
                    + String.join(", ", broken) + ")" + (notRun == 0 ? "" : "; " + notRun + " not run: "
                    + contract.get(contract.size() - 1).notRun());
        List<String> weak = quality.stream().filter(c -> !c.passed()).map(GradeCommand.Check::name).toList();
        StringBuilder v = new StringBuilder(weak.isEmpty() ? "GOOD" : "CORRECT");
        v.append(": honours the contract (").append(contract.size()).append(" of ").append(contract.size()).append(" checks); ");
        v.append(weak.isEmpty() ? "passes every quality check" : "fails quality: " + String.join(", ", weak));
        for (String b : GradeCommand.BUILT_INS) v.append("; cheaper than ").append(b).append(" on ").append(cheaper(rows, b));
        return v.toString();
    }

    /** "k of n scenes": where the graded builder's tree has a lower expected cost than built-in {@code b}'s. */
    private static String cheaper(List<GradeCommand.Row> rows, String b) {
        int n = 0, k = 0;
        for (int i = 0; i < rows.size(); i += GradeCommand.BUILT_INS.size() + 1) {
            GradeCommand.Row own = rows.get(i);
            GradeCommand.Row other = rows.get(i + 1 + GradeCommand.BUILT_INS.indexOf(b));
            n++;
            if (own.cost() < other.cost()) k++;
        }
        return k + " of " + n + " scenes";
    }
}
