package org.kdtree.cli;

import java.io.File;
import java.io.IOException;
import java.io.InputStream;
import java.net.URISyntaxException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.jar.JarFile;
import org.kdtree.check.TreeTape;
import org.kdtree.limits.Deadlines;

/**
 * One student's grade: the student's builder runs in a JVM of its own ({@link StudentMain}), in an operating-system box ({@link StudentBox}) unless there is none, and the
 * grade is made here, outside it. So students' builders of the same name never meet; one that
 * hangs, calls System.exit or fills its heap ends only its own JVM (killed at the student deadline,
 * bounded by {@code -Xmx}); and whatever its code writes cannot change its verdict: its JVM sends
 * each tree it built (a {@link TreeTape}), and this JVM replays the same checks on those trees,
 * building the scenes' built-ins itself. A report that does not match the checks is the builder's
 * fault, named in its row.
 *
 * <p>Each child is started as {@link JvmStart} says. The build times a student's are compared
 * with are the library's SAH's timed in a child started the same way ({@link #withReference}),
 * not this JVM's.
 *
 * @param deadlines the per-call and per-build deadlines the child enforces itself
 * @param seconds   the student deadline: the child is killed past it
 * @param heapMb    the child's heap
 * @param box       the box each child runs in, or null for none ({@code --no-sandbox})
 * @param start     how each child is started
 * @param sahMillis the library's SAH's build time on each course scene in such a child, or null for this JVM's own
 */
record StudentJvm(Deadlines deadlines, double seconds, int heapMb, StudentBox box, JvmStart start, Map<String, Double> sahMillis) {
    /** A child started plainly, the SAH's times this JVM's own: see {@link #withReference}. */
    StudentJvm(Deadlines deadlines, double seconds, int heapMb, StudentBox box) {
        this(deadlines, seconds, heapMb, box, JvmStart.PLAIN, null);
    }

    /** The reference's row name: the library's SAH, graded as a student is. */
    static final String REFERENCE = "the library's sah";

    /** How long a child may take to end once its report is done, before it is killed. */
    static final double GRACE_SECONDS = 5;
    /** A graded jar: its row, and the report made here (null if the jar was not graded to the end). */
    record Graded(StudentRow row, Report report) {
    }

    /** Grades {@code jar}, with the report made here; never throws for a bad jar or a bad builder: the row says what happened. */
    Graded run(Path jar) {
        return run(jar, null);
    }

    /**
     * This, with the library's SAH's build times taken in a child started as the students' are
     * (the same compiler, collector and classes), so that a student's build time is compared with
     * the SAH's in the same kind of JVM; unchanged, saying why on standard error, if that run fails.
     */
    StudentJvm withReference() {
        Graded ref = run(null, null);
        if (ref.report() != null) return timedBy(ref);
        System.err.println("warning: the library's SAH could not be timed as the students are (" + ref.row().problem()
                + "): their build times are compared with this JVM's");
        return this;
    }

    /**
     * This, for a class: the library's classes archived once in {@code folder} by a trusted run
     * (the library's SAH graded as a student is), each student's JVM then mapping them; and the
     * SAH's reference times ({@link #withReference}), taken in a JVM that must map the archive, so
     * that an archive the JVM cannot use is found here, said in one line, and not used.
     */
    StudentJvm forClass(Path folder) throws IOException {
        Path dir = Files.createDirectory(folder.resolve("cds"));
        dir.toFile().setWritable(true, false); // the box's user (nobody, for a root teacher) writes the archive
        dir.toFile().setExecutable(true, false);
        Graded dump = run(null, dir);
        Path archive = dir.resolve(JvmStart.FILE);
        if (dump.report() == null || !Files.isRegularFile(archive)) {
            System.err.println("warning: the library's classes could not be archived for the class (" + (dump.report() == null
                    ? dump.row().problem() : "the JVM made no archive: are they a folder rather than a jar?") + "): each student's JVM reads them itself");
            return withReference();
        }
        Graded ref = with(new JvmStart(archive, true)).run(null, null);
        if (ref.report() != null) return with(new JvmStart(archive, false)).timedBy(ref);
        System.err.println("warning: the class's archive of the library's classes cannot be used here (" + ref.row().problem()
                + "): each student's JVM reads them itself");
        return withReference();
    }

    StudentJvm with(JvmStart s) {
        return new StudentJvm(deadlines, seconds, heapMb, box, s, sahMillis);
    }

    /** This, the SAH's build times those of the reference's report. */
    private StudentJvm timedBy(Graded ref) {
        Map<String, Double> ms = new HashMap<>();
        List<GradeCommand.Row> rows = ref.report().rows();
        for (int i = 0; i < rows.size(); i += GradeCommand.BUILT_INS.size() + 1) ms.put(rows.get(i).scene(), rows.get(i).ms());
        return new StudentJvm(deadlines, seconds, heapMb, box, start, Map.copyOf(ms));
    }

    /** Grades {@code jar}, or the library's SAH if it is null (archiving the classes it loaded into {@code dumpInto} unless that is null). */
    private Graded run(Path jar, Path dumpInto) {
        String file = jar == null ? REFERENCE : jar.getFileName().toString(), student = jar == null ? REFERENCE : student(jar);
        String boxed = box == null ? "none (--no-sandbox)" : "bubblewrap";
        long t0 = System.nanoTime();
        Process p;
        try {
            ProcessBuilder pb = new ProcessBuilder(command(jar, dumpInto));
            pb.redirectInput(box == null || jar == null ? ProcessBuilder.Redirect.from(StudentBox.nullDevice())
                    : ProcessBuilder.Redirect.from(jar.toFile()));
            p = pb.start();
        } catch (IOException e) {
            return new Graded(StudentRow.failed(file, student, "not graded: " + e.getMessage(), 0, boxed), null);
        }
        AtomicBoolean killed = new AtomicBoolean();
        Thread dog = watchdog(p, killed);
        CompletableFuture<String> err = tail(p.getErrorStream());
        Report report = null;
        TreeTape.Mismatch mismatch = null;
        TreeTape.Player tape = null;
        try {
            tape = new TreeTape.Player(p.getInputStream());
            TreeTape.Player replay = tape;
            report = new GradeRun(replay::builder, replay, sahMillis).run(replay.builderName(), deadlines, new ProgressBar(null, 1, "checks"));
            tape.end();
        } catch (TreeTape.Mismatch m) {
            mismatch = m;
            report = null;
        } catch (RuntimeException | Error ours) { // a bug of ours: the child is not left running
            killQuietly(p);
            throw ours;
        }
        List<String> notes = new ArrayList<>();
        try {
            CompletableFuture<Long> rest = drain(tape, p);
            if (mismatch != null && !mismatch.early()) kill(p); // its grade is void: no need to wait for the rest
            if (report != null && !p.waitFor((long) (GRACE_SECONDS * 1000), TimeUnit.MILLISECONDS)) {
                kill(p);
                notes.add(String.format(Locale.ROOT, "its JVM did not end within %.0f s of its report: killed", GRACE_SECONDS));
            }
            dog.join(); // the child has ended, or was killed at the deadline
            long after = rest.completeOnTimeout(-1L, 5, TimeUnit.SECONDS).get(); // -1: a process it started still holds the channel
            if (report != null && after > 0) notes.add("wrote " + after + " bytes into its report channel after the report: ignored");
            double took = (System.nanoTime() - t0) / 1e9;
            String said = err.completeOnTimeout("", 5, TimeUnit.SECONDS).get();
            StudentRow row;
            if (report != null) row = StudentRow.parse(file, student, report.csv(), took, boxed);
            else if (killed.get()) row = StudentRow.failed(file, student, String.format(Locale.ROOT,
                    "crashed: killed at the student deadline of %.0f s", seconds), took, boxed);
            else if (mismatch.early()) row = StudentRow.failed(file, student, why(p.exitValue(), said, jar), took, boxed);
            else row = StudentRow.failed(file, student, "its report does not match the checks made of it (" + mismatch.getMessage()
                    + "): its code wrote into the report channel?", took, boxed);
            if (box != null) {
                String stopped = StudentBox.stopped(String.join(" ", row.failure(), row.quality(), row.problem(), said));
                if (!stopped.isEmpty()) notes.add(stopped);
            }
            for (String n : notes) row = row.withNote(n);
            return new Graded(row, report);
        } catch (java.util.concurrent.ExecutionException e) {
            return new Graded(StudentRow.failed(file, student, "not graded: " + e.getMessage(), (System.nanoTime() - t0) / 1e9, boxed), null);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            killQuietly(p);
            return new Graded(StudentRow.failed(file, student, "not graded: interrupted", (System.nanoTime() - t0) / 1e9, boxed), null);
        }
    }

    /** Kills the child at the student deadline (noting it in {@code killed}); ends when the child has. */
    private Thread watchdog(Process p, AtomicBoolean killed) {
        Thread t = new Thread(() -> {
            try {
                if (!p.waitFor((long) (seconds * 1000), TimeUnit.MILLISECONDS)) {
                    killed.set(true);
                    kill(p);
                }
            } catch (InterruptedException e) {
                killQuietly(p);
            }
        }, "student-deadline");
        t.setDaemon(true);
        t.start();
        return t;
    }

    /** Reads the child's standard output to its end on a thread of its own (a child blocks on a full pipe); yields how many bytes followed the tape's end. */
    private static CompletableFuture<Long> drain(TreeTape.Player tape, Process p) {
        CompletableFuture<Long> f = new CompletableFuture<>();
        Thread t = new Thread(() -> {
            try {
                f.complete(tape != null ? tape.drainRest() : p.getInputStream().transferTo(java.io.OutputStream.nullOutputStream()));
            } catch (IOException e) {
                f.complete(0L);
            }
        }, "student-stdout");
        t.setDaemon(true);
        t.start();
        return f;
    }

    /**
     * Why a child ended without its report, from what it said, not from its exit code alone (a
     * builder may pass any code to System.exit, 2, 3 and 4 included): the grading JVM's own
     * one-line error ({@link Failure}: "error: ..." as its last line, with its code), the JVM's
     * out-of-memory error, or else an exit the builder made.
     */
    String why(int code, String err, Path jar) {
        String last = err.strip();
        last = last.substring(last.lastIndexOf('\n') + 1).strip();
        boolean ours = last.startsWith("error: ");
        String said = last.replaceFirst("^error: ", "");   // the library names the jar it loaded: the row names it already
        for (String named : jar == null ? List.<String>of() : List.of(jar.toAbsolutePath() + ": ", StudentBox.jarInside(jar.getFileName().toString()) + ": "))
            if (said.startsWith(named)) said = said.substring(named.length());
        if (ours && code == Failure.MEMORY && said.startsWith("out of memory") || err.contains("java.lang.OutOfMemoryError"))
            return "crashed: out of memory (heap " + heapMb + " MB)";
        if (ours && code == Failure.USAGE) return "not graded: " + StudentRow.oneLine(said);
        if (ours && code == Failure.BUILDER) return "crashed: " + StudentRow.oneLine(said);
        if (code > 128 && code < 160)
            return "crashed: the JVM was ended by signal " + (code - 128) + " (exit code " + code + ") before the grade was done";
        return "crashed: the JVM exited with code " + code + " before the grade was done (System.exit(" + code + ") in the builder?)"
                + (last.isBlank() ? "" : ": " + StudentRow.oneLine(last));
    }

    /**
     * The child's command line: this JVM's java, the library's class path, the student's jar (none
     * for the reference: the library's SAH) and nothing else; in its box if there is one.
     */
    private List<String> command(Path jar, Path dumpInto) {
        List<String> jvm = new ArrayList<>(start.options(heapMb, box != null));
        List<String> binds = new ArrayList<>(start.binds());
        if (dumpInto != null) {
            jvm.addAll(JvmStart.dump(dumpInto, box != null));
            binds.addAll(JvmStart.dumpBinds(dumpInto));
        }
        String name = jar == null ? "none.jar" : jar.getFileName().toString();
        List<String> main = new ArrayList<>(List.of(StudentMain.class.getName()));
        if (jar == null) main.add("--reference");
        else main.addAll(List.of("--student-jar", box != null ? StudentBox.jarInside(name) : jar.toAbsolutePath().toString()));
        main.addAll(List.of("--call-deadline", Double.toString(deadlines.callSeconds()), "--build-deadline", Double.toString(deadlines.buildSeconds())));
        if (box != null) return box.command(Arrays.asList(classPath().split(File.pathSeparator)), binds, jvm, name, main);
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString()));
        cmd.addAll(jvm);
        cmd.addAll(List.of("-cp", classPath()));
        cmd.addAll(main);
        return cmd;
    }

    /**
     * This JVM's class path without its folders other than the library's own: the jars (the
     * library's, its dependencies') stay, a test's class folder (holding other students' builders) goes.
     */
    static String classPath() {
        String own;
        try {
            own = Path.of(Main.class.getProtectionDomain().getCodeSource().getLocation().toURI()).toString();
        } catch (URISyntaxException e) {
            throw new IllegalStateException("cannot locate the library's own classes", e);
        }
        List<String> keep = new ArrayList<>(List.of(own));
        for (String entry : System.getProperty("java.class.path").split(File.pathSeparator))
            if (!entry.equals(own) && Files.isRegularFile(Path.of(entry))) keep.add(entry);
        return String.join(File.pathSeparator, keep);
    }

    /**
     * The student's name as the student declared it: the jar's manifest's Implementation-Vendor
     * (the starter project writes its {@code student} property there); else the coordinates of the
     * pom Maven put in the jar ({@code groupId:artifactId}), unless they are the starter's own; else
     * the jar's file name without {@code .jar}, as the teacher named it. Never Built-By: that is
     * the login of whoever built the jar ({@code root} in a container), which names no student.
     */
    static String student(Path jar) {
        try (JarFile j = new JarFile(jar.toFile())) {
            var m = j.getManifest();
            if (m != null) {
                String v = m.getMainAttributes().getValue("Implementation-Vendor");
                if (v != null && !v.isBlank()) return v.strip();
            }
            for (var e : java.util.Collections.list(j.entries())) {
                if (!e.getName().startsWith("META-INF/maven/") || !e.getName().endsWith("/pom.properties")) continue;
                java.util.Properties pom = new java.util.Properties();
                try (InputStream in = j.getInputStream(e)) {
                    pom.load(in);
                }
                String coordinates = pom.getProperty("groupId", "") + ":" + pom.getProperty("artifactId", "");
                if (!coordinates.equals(STARTER_COORDINATES) && !coordinates.equals(":")) return coordinates;
            }
        } catch (IOException | SecurityException | IllegalArgumentException notAJar) {
            // not a jar: the file's name is all there is
        }
        return jar.getFileName().toString().replaceFirst("(?i)\\.jar$", "");
    }

    /** The starter project's groupId:artifactId, which names no one. */
    static final String STARTER_COORDINATES = "course.kdtree:my-builder";

    /** Kills the child and whatever it started, and waits for it to be gone. */
    private static void kill(Process p) throws InterruptedException {
        p.descendants().forEach(ProcessHandle::destroyForcibly);
        p.destroyForcibly();
        p.waitFor();
    }

    private static void killQuietly(Process p) {
        p.descendants().forEach(ProcessHandle::destroyForcibly);
        p.destroyForcibly();
    }

    /** The most of a child's standard error kept: its end, where its last line is. */
    private static final int TAIL = 64 << 10;

    /** Reads the stream to its end on a thread of its own (a child blocks on a full pipe), keeping only its tail (its last {@value #TAIL} bytes). */
    private static CompletableFuture<String> tail(InputStream in) {
        CompletableFuture<String> f = new CompletableFuture<>();
        Thread t = new Thread(() -> {
            byte[] ring = new byte[TAIL];
            long total = 0;
            try (in) {
                byte[] buf = new byte[8192];
                for (int k; (k = in.read(buf)) >= 0; ) {
                    for (int i = 0; i < k; i++) ring[(int) ((total + i) % TAIL)] = buf[i];
                    total += k;
                }
            } catch (IOException ended) {
                // what was read is what there is
            }
            int n = (int) Math.min(total, TAIL);
            byte[] last = new byte[n];
            for (int i = 0; i < n; i++) last[i] = ring[(int) ((total - n + i) % TAIL)];
            f.complete(new String(last, StandardCharsets.UTF_8).strip());
        }, "student-stderr");
        t.setDaemon(true);
        t.start();
        return f;
    }
}
