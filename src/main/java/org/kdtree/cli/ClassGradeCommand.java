package org.kdtree.cli;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.atomic.AtomicInteger;
import org.kdtree.check.CourseScenes;
import org.kdtree.files.AtomicFile;
import org.kdtree.limits.Deadlines;
import org.kdtree.limits.Limits;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * {@code grade-class FOLDER}: every jar of a folder graded as {@code grade} grades one builder,
 * each in a JVM of its own in a box (see {@link StudentJvm}, {@link StudentBox}), several at once, into one table.
 */
@Command(name = "grade-class", mixinStandardHelpOptions = true,
        description = {"Grade a class: every .jar in FOLDER graded alone in a JVM of its own (a hang, System.exit or "
                + "unbounded allocation ends only that student's run), several at once, into one table (CSV and Markdown): "
                + "one row per jar, failures first.",
                "Each JVM runs in a box (bubblewrap): no network, no file but the system, the JDK, the library and its own jar, "
                        + "a 64 MB scratch folder, at most 256 threads; the grade is made outside it, from the trees it sends.",
                "Exit code 0 once the table is written, whatever the verdicts; 2 if a file of it could not be written "
                        + "(the table is then printed, and kept in a temporary file the error names)."})
final class ClassGradeCommand implements Callable<Integer> {
    @Parameters(paramLabel = "FOLDER", description = "The students' jars (every .jar file in it; other files are not looked at).")
    Path folder;

    @Option(names = "--csv", paramLabel = "FILE", defaultValue = "class-grades.csv", description = "The table as CSV (default: ${DEFAULT-VALUE}).")
    Path csv;

    @Option(names = "--markdown", paramLabel = "FILE", defaultValue = "class-grades.md",
            description = "The table as Markdown, with how many of each verdict (default: ${DEFAULT-VALUE}).")
    Path markdown;

    @Option(names = "--roster", paramLabel = "FILE", description = "The class's roster: a CSV file with the header file,name,id "
            + "(the jar's file name, the student's name and id), which names the rows; a student without a jar, and a jar "
            + "not on it, are each said in one line.")
    Path roster;

    @Mixin
    ScoringOptions scoring;

    @Option(names = {"-j", "--jobs"}, paramLabel = "N",
            description = "Students graded at once (default: the cores, fewer if memory is short for that many heaps).")
    Integer jobs;

    @Option(names = "--student-deadline", paramLabel = "SECONDS",
            description = "A student's JVM still running after this is killed (default: 300; 1 to 86400).")
    Double studentSeconds;

    @Option(names = "--student-heap", paramLabel = "MB", description = "Each student's JVM's heap, -Xmx (default: 512; 64 to 65536).")
    Integer heapMb;

    @Option(names = "--no-sandbox", description = "Run the students' JVMs without a box (where bubblewrap cannot run); "
            + "every row says so.")
    boolean noSandbox;

    @Mixin
    ProgressOption progress;

    @Mixin
    DeadlineOptions deadlines;

    @Override public Integer call() throws IOException, InterruptedException {
        List<Path> jars = jars();
        for (Path out : List.of(csv, markdown)) CommandFiles.requireWritable(out == csv ? "--csv" : "--markdown", out);
        if (scoring.junitXml != null) CommandFiles.requireWritable("--junit-xml", scoring.junitXml);
        for (Path out : java.util.Arrays.asList(csv, markdown, scoring.junitXml)) {   // a table never replaces the roster or the rubric
            CommandFiles.requireNotInput("an output", out, "--roster", roster);
            CommandFiles.requireNotInput("an output", out, "--rubric", scoring.rubric);
        }
        Roster names = roster == null ? null : Roster.read("--roster", roster);
        Rubric points = scoring.read();
        StudentJvm plain = new StudentJvm(deadlines.deadlines(Deadlines.GRADE), seconds(), heap(), box(noSandbox, "grade-class"));
        int n = jobs == null ? defaultJobs(plain.heapMb()) : jobs;
        Limits.THREADS.check("--jobs", n);
        long t0 = System.nanoTime();
        Path scratch = Files.createTempDirectory("grade-class-");
        List<StudentJvm.Graded> graded;
        StudentJvm jvm;
        try {
            jvm = plain.forClass(scratch);
            graded = gradeAll(jars, jvm, n);
        } finally {
            deleteQuietly(scratch);
        }
        List<StudentRow> rows = graded.stream().map(StudentJvm.Graded::row).toList();
        List<String> rosterLines = List.of();
        if (names != null) {
            rows = names.name(rows);
            rosterLines = names.mismatches(jars.stream().map(j -> j.getFileName().toString()).toList());
        }
        List<Scorecard> cards = new ArrayList<>();
        Rubric worth = ScoringOptions.orOnePointEach(points);
        for (int i = 0; i < rows.size(); i++) cards.add(Scorecard.of(worth, rows.get(i), graded.get(i).report()));
        Map<String, Scorecard> scores = new LinkedHashMap<>();
        if (points != null) for (Scorecard c : cards) scores.put(c.row().file(), c);
        ClassTable table = new ClassTable(rows, CourseScenes.all().stream().map(CourseScenes.Named::name).toList(), scores, rosterLines);
        System.out.print(table.markdown());
        List<String> lost = save(table, csv, markdown);
        if (scoring.junitXml != null) save(scoring.junitXml, JunitXml.of(cards), ".xml", lost);
        System.out.printf(Locale.ROOT, "%ngraded in %.0f s, %d at once (%s); table: %s, %s%s%n", (System.nanoTime() - t0) / 1e9, n,
                jvm.start().describe(), csv, markdown, scoring.junitXml == null ? "" : "; JUnit XML: " + scoring.junitXml);
        rosterLines.forEach(System.out::println);
        lost.forEach(System.err::println);
        return lost.isEmpty() ? 0 : Failure.USAGE;
    }

    /**
     * Writes the table's two files; one that cannot be written (its folder made read-only, the
     * disk full, while the class was graded) is written to a temporary file instead, so that
     * no finished grade is lost. {@return one line for each file not written where asked, saying where it is}
     */
    static List<String> save(ClassTable table, Path csv, Path markdown) {
        List<String> lost = new ArrayList<>();
        save(csv, table.csv(), ".csv", lost);
        save(markdown, table.markdown(), ".md", lost);
        return lost;
    }

    /** Writes {@code file}; if it cannot be, keeps the content in a temporary file ending {@code ext} and adds to {@code lost} where. */
    static void save(Path file, String content, String ext, List<String> lost) {
        try {
            AtomicFile.writeString(file, content);
        } catch (IOException e) {
            try {
                Path kept = Files.createTempFile("class-grades-", ext);
                AtomicFile.writeString(kept, content);
                lost.add("error: " + e.getMessage() + "; the table is kept in " + kept);
            } catch (IOException again) {
                lost.add("error: " + e.getMessage() + "; the table is only in the output above");
            }
        }
    }

    /** Every student at once up to {@code n}, each on a thread that waits for its JVM; the bar counts those done. */
    private List<StudentJvm.Graded> gradeAll(List<Path> jars, StudentJvm jvm, int n) throws InterruptedException {
        ExecutorService pool = Executors.newFixedThreadPool(n);
        AtomicInteger done = new AtomicInteger();
        try (ProgressBar bar = progress.bar(jars.size(), "students")) {
            bar.step(0, n + " at once"); // drawn now, so that the first minute shows the time too
            List<Future<StudentJvm.Graded>> running = new ArrayList<>();
            for (Path jar : jars) running.add(pool.submit(() -> {
                StudentJvm.Graded g = jvm.run(jar);
                bar.update(done.incrementAndGet());
                return g;
            }));
            List<StudentJvm.Graded> rows = new ArrayList<>();
            for (Future<StudentJvm.Graded> f : running) rows.add(f.get());
            return rows;
        } catch (ExecutionException e) {
            throw new IllegalStateException("grading a student failed: " + e.getCause(), e.getCause());
        } finally {
            pool.shutdownNow();
        }
    }

    /** Deletes the class's scratch folder (its archive); what cannot be deleted stays in the temporary folder. */
    private static void deleteQuietly(Path folder) {
        try (var all = Files.walk(folder)) {
            for (Path p : all.sorted(java.util.Comparator.reverseOrder()).toList()) Files.deleteIfExists(p);
        } catch (IOException | java.io.UncheckedIOException leftInTmp) {
            // a temporary folder: the system's to clear
        }
    }

    private List<Path> jars() throws IOException {
        if (!Files.isDirectory(folder))
            throw new IllegalArgumentException("grade-class " + folder + (Files.exists(folder)
                    ? ": is a file, not a folder; give the folder of the students' jars (one student's jar: grade --student-jar JAR)"
                    : ": no such folder"));
        try (var files = Files.list(folder)) {
            List<Path> jars = files.filter(f -> f.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".jar")).sorted().toList();
            if (jars.isEmpty()) throw new IllegalArgumentException("grade-class " + folder + ": the folder holds no .jar");
            return jars;
        }
    }

    /** The box the students' JVMs run in, none if {@code unboxed}; refused in one line where none can be made. */
    static StudentBox box(boolean unboxed, String command) {
        if (unboxed) return null;
        try {
            return StudentBox.find();
        } catch (StudentBox.Unavailable e) {
            throw new IllegalArgumentException(command + " runs each student's code in a box, and none can be made here: "
                    + e.getMessage() + " (or grade without a box: --no-sandbox)");
        }
    }

    private double seconds() {
        if (studentSeconds == null) return Limits.STUDENT_SECONDS;
        Limits.STUDENT_DEADLINE.check("--student-deadline", studentSeconds);
        return studentSeconds;
    }

    private int heap() {
        if (heapMb == null) return Limits.STUDENT_HEAP_MB;
        Limits.STUDENT_HEAP.check("--student-heap", heapMb);
        return heapMb;
    }

    /** The cores, but no more heaps than half the machine's memory holds (the rest: the JVMs' own, the system's). */
    static int defaultJobs(int heapMb) {
        int cores = Runtime.getRuntime().availableProcessors();
        if (!(java.lang.management.ManagementFactory.getOperatingSystemMXBean() instanceof com.sun.management.OperatingSystemMXBean os))
            return cores;
        long fit = os.getTotalMemorySize() / 2 / ((long) heapMb << 20);
        return (int) Math.max(1, Math.min(cores, fit));
    }
}
