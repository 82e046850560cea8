package org.kdtree.cli;

import java.io.File;
import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.net.URISyntaxException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.jar.JarFile;
import org.kdtree.limits.Deadlines;

/**
 * One student's grade in a JVM of its own ({@code grade --student-jar JAR -o grade.csv}), so that
 * students' builders of the same name never meet, and one that hangs, calls System.exit or fills
 * its heap ends only its own JVM: killed at the student deadline, bounded by {@code -Xmx}.
 *
 * @param deadlines the per-call and per-build deadlines the child enforces itself
 * @param seconds   the student deadline: the child is killed past it
 * @param heapMb    the child's heap
 */
record StudentJvm(Deadlines deadlines, double seconds, int heapMb) {

    /** Grades {@code jar}; never throws for a bad jar or a bad builder: the row says what happened. */
    StudentRow grade(Path jar) {
        String file = jar.getFileName().toString(), student = student(jar);
        long t0 = System.nanoTime();
        Path dir = null;
        try {
            dir = Files.createTempDirectory("kdtree-grade-");
            Path csv = dir.resolve("grade.csv");
            Process p = new ProcessBuilder(command(jar, csv)).redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
            CompletableFuture<String> err = tail(p.getErrorStream());
            boolean finished = p.waitFor((long) (seconds * 1000), TimeUnit.MILLISECONDS);
            if (!finished) kill(p);
            double took = (System.nanoTime() - t0) / 1e9;
            if (!finished) return StudentRow.failed(file, student, String.format(Locale.ROOT,
                    "crashed: killed at the student deadline of %.0f s", seconds), took);
            if (Files.isRegularFile(csv)) return StudentRow.parse(file, student, Files.readString(csv), took);
            return StudentRow.failed(file, student, why(p.exitValue(), err.get(5, TimeUnit.SECONDS), jar), took);
        } catch (IOException | java.util.concurrent.ExecutionException | java.util.concurrent.TimeoutException e) {
            return StudentRow.failed(file, student, "not graded: " + e.getMessage(), (System.nanoTime() - t0) / 1e9);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return StudentRow.failed(file, student, "not graded: interrupted", (System.nanoTime() - t0) / 1e9);
        } finally {
            removeQuietly(dir);
        }
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
        String said = last.replaceFirst("^error: ", "").replace("--plugin " + jar.toAbsolutePath() + ": ", "");
        if (ours && code == Failure.MEMORY && said.startsWith("out of memory") || err.contains("java.lang.OutOfMemoryError"))
            return "crashed: out of memory (heap " + heapMb + " MB)";
        if (ours && code == Failure.USAGE) return "not graded: " + StudentRow.oneLine(said);
        if (ours && code == Failure.BUILDER) return "crashed: " + StudentRow.oneLine(said);
        if (code > 128 && code < 160)
            return "crashed: the JVM was ended by signal " + (code - 128) + " (exit code " + code + ") before the grade was done";
        return "crashed: the JVM exited with code " + code + " before the grade was done (System.exit(" + code + ") in the builder?)"
                + (last.isBlank() ? "" : ": " + StudentRow.oneLine(last));
    }

    /** The child's command line: this JVM's java, the library's class path, the student's jar and nothing else. */
    private List<String> command(Path jar, Path csv) {
        return List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Xmx" + heapMb + "m", "-Djava.awt.headless=true", "-cp", classPath(), Main.class.getName(), "grade",
                "--student-jar", jar.toAbsolutePath().toString(), "-o", csv.toString(), "--quiet",
                "--call-deadline", Double.toString(deadlines.callSeconds()), "--build-deadline", Double.toString(deadlines.buildSeconds()));
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
     * The student's name: the jar's manifest's Implementation-Vendor (the starter project writes
     * its {@code student} property there), else Built-By; else the coordinates of the pom Maven
     * put in the jar ({@code groupId:artifactId}), unless they are the starter's own; else "".
     */
    static String student(Path jar) {
        try (JarFile j = new JarFile(jar.toFile())) {
            var m = j.getManifest();
            if (m != null) {
                String v = m.getMainAttributes().getValue("Implementation-Vendor");
                if (v == null || v.isBlank()) v = m.getMainAttributes().getValue("Built-By");
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
            return "";
        } catch (IOException | SecurityException | IllegalArgumentException notAJar) {
            return "";
        }
    }

    /** The starter project's groupId:artifactId, which names no one. */
    static final String STARTER_COORDINATES = "course.kdtree:my-builder";

    /** Kills the child and whatever it started, and waits for it to be gone. */
    private static void kill(Process p) throws InterruptedException {
        p.descendants().forEach(ProcessHandle::destroyForcibly);
        p.destroyForcibly();
        p.waitFor();
    }

    /**
     * Reads the stream to its end on a thread of its own (a child blocks on a full pipe); yields
     * its last 64 KB (a student's builder may print without bound).
     */
    private static CompletableFuture<String> tail(InputStream in) {
        CompletableFuture<String> f = new CompletableFuture<>();
        Thread t = new Thread(() -> {
            try (in) {
                byte[] ring = new byte[1 << 16];
                long total = 0;
                byte[] buf = new byte[8192];
                for (int n; (n = in.read(buf)) > 0; total += n)
                    for (int i = 0; i < n; i++) ring[(int) ((total + i) % ring.length)] = buf[i];
                int len = (int) Math.min(total, ring.length), start = (int) ((total - len) % ring.length);
                byte[] last = new byte[len];
                for (int i = 0; i < len; i++) last[i] = ring[(start + i) % ring.length];
                f.complete(new String(last, StandardCharsets.UTF_8));
            } catch (IOException e) {
                f.complete("");
            }
        }, "student-stderr");
        t.setDaemon(true);
        t.start();
        return f;
    }

    private static void removeQuietly(Path dir) {
        if (dir == null) return;
        try (var files = Files.walk(dir)) {
            for (Path f : files.sorted(Comparator.reverseOrder()).toList()) Files.deleteIfExists(f);
        } catch (IOException | UncheckedIOException leftInTemp) {
            // a temporary folder left behind is harmless
        }
    }
}
