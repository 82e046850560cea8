package org.kdtree.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kdtree.testing.PluginJars;
import org.kdtree.testing.ReadOnlyFolder;
import org.kdtree.testing.StudentJars;

/** grade-class over a folder of ten students' jars, good and broken in every way: one complete table, in bounded time and memory. */
class ClassGradeCommandTest {
    private static final String T = "org.kdtree.testing.";

    @Test void aClassOfTenJarsGivesOneRowEachWithWhatWentWrong(@TempDir Path dir) throws Exception {
        BoxTests.assumeABoxCanBeMade();
        Path jars = Files.createDirectory(dir.resolve("jars"));
        jar(jars, "alice.jar", "Alice", "PluginMidpointBuilder");
        jar(jars, "bob.jar", "Bob", "PluginMidpointBuilder"); // the same builder name as Alice's
        jar(jars, "carol.jar", "Carol", "ThrowingBuilder");
        jar(jars, "dan.jar", "Dan", "PlaneOutsideBuilder");
        jar(jars, "erin.jar", "Erin", "LoopingFindPlaneBuilder", "Spin");
        jar(jars, "frank.jar", "Frank", "ExitingBuilder");
        jar(jars, "grace.jar", "Grace", "HoardingBuilder");
        jar(jars, "heidi.jar", "Heidi", "", "PluginMidpointBuilder"); // the class, but no services file
        PluginJars.student(jars, "ivan.jar", "Ivan", new String[] {T + "ThrowingBuilder", T + "PlaneOutsideBuilder"},
                new String[0]);
        Files.writeString(jars.resolve("judy.jar"), "my notes, not a jar");
        Path csv = dir.resolve("class.csv"), md = dir.resolve("class.md");

        long t0 = System.nanoTime();
        CliRun run = CliRun.of("grade-class", jars.toString(), "--csv", csv.toString(), "--markdown", md.toString(), "-q",
                "--jobs", "2", "--student-heap", "128", "--student-deadline", "40", "--call-deadline", "1", "--build-deadline", "10");   // room for a loaded machine
        double seconds = (System.nanoTime() - t0) / 1e9;

        assertThat(run.code()).as(run.err()).isZero();
        assertThat(seconds).isLessThan(60);
        Map<String, Map<String, String>> rows = rows(Files.readString(csv, StandardCharsets.UTF_8));
        assertThat(rows).hasSize(10);
        for (String good : List.of("alice.jar", "bob.jar")) {
            assertThat(rows.get(good).get("verdict")).as(good + ": " + rows.get(good)).isIn("CORRECT", "GOOD");
            assertThat(rows.get(good).get("builder")).isEqualTo("plugin-midpoint");
            assertThat(rows.get(good).get("cost_vs_median")).isNotEmpty();
        }
        assertThat(rows.get("alice.jar").get("student")).isEqualTo("Alice");
        assertThat(rows.get("carol.jar").get("first_failure")).contains("ArrayIndexOutOfBoundsException");
        assertThat(rows.get("dan.jar").get("first_failure")).contains("outside the voxel");
        assertThat(rows.get("erin.jar").get("problem")).contains("hung in findPlane");
        assertThat(rows.get("frank.jar").get("problem")).contains("crashed", "code 42");
        assertThat(rows.get("grace.jar").get("first_failure") + rows.get("grace.jar").get("problem")).containsIgnoringCase("memory");
        assertThat(rows.get("heidi.jar").get("problem")).contains("not graded: the jar lists no builder; add the file");
        assertThat(rows.get("ivan.jar").get("problem")).contains("lists 2 builders");
        assertThat(rows.get("judy.jar").get("problem")).isEqualTo("not graded: not a jar (zip) file");
        for (String bad : List.of("carol.jar", "dan.jar", "erin.jar", "frank.jar", "grace.jar", "heidi.jar", "ivan.jar", "judy.jar"))
            assertThat(rows.get(bad).get("verdict")).as(bad).isEqualTo("FAIL");
        assertThat(Files.readString(md)).contains("10 jars: 8 FAIL").contains("| alice.jar | Alice |  | plugin-midpoint |");
    }

    /** Issue 34, item 3: a builder's System.exit(n) is told from running out of memory by what the JVM said, for any n. */
    @Test void aBuildersExitIsNeverReportedAsOutOfMemoryWhateverItsCode(@TempDir Path dir) throws Exception {
        BoxTests.assumeABoxCanBeMade();
        Path jars = Files.createDirectory(dir.resolve("jars"));
        for (int code : new int[] {2, 3, 4, 42})
            StudentJars.compile(jars, "exit" + code + ".jar", "my-builder", 2, "System.exit(" + code + "); return null;");
        Path csv = dir.resolve("class.csv");
        CliRun run = CliRun.of("grade-class", jars.toString(), "--csv", csv.toString(), "--markdown", dir.resolve("class.md").toString(),
                "-q", "--jobs", "2", "--student-heap", "128", "--student-deadline", "60");
        assertThat(run.code()).as(run.err()).isZero();
        Map<String, Map<String, String>> rows = rows(Files.readString(csv, StandardCharsets.UTF_8));
        for (int code : new int[] {2, 3, 4, 42})
            assertThat(rows.get("exit" + code + ".jar").get("problem")).as("exit " + code)
                    .isEqualTo("crashed: the JVM exited with code " + code + " before the grade was done (System.exit(" + code
                            + ") in the builder?)");
    }

    /** Runs wherever the box cannot be made too: the refusal is what a teacher without bubblewrap sees. */
    @Test void withoutBubblewrapGradeClassRefusesInOneLineSayingWhatToInstall(@TempDir Path other) throws Exception {
        StudentJars.compile(other, "a.jar", "my-builder", 2, "return null;");
        Path java = Path.of(System.getProperty("java.home"), "bin", "java");
        ProcessBuilder pb = new ProcessBuilder(java.toString(), "-cp", StudentJvm.classPath(), Main.class.getName(), "grade-class",
                other.toString(), "--csv", other.resolve("c.csv").toString()).redirectErrorStream(true);
        pb.environment().put("PATH", Files.createDirectory(other.resolve("empty")).toString());
        Process p = pb.start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8).strip();
        assertThat(p.waitFor(60, TimeUnit.SECONDS)).isTrue();
        assertThat(p.exitValue()).isEqualTo(Failure.USAGE);
        assertThat(out.lines()).hasSize(1);
        assertThat(out).startsWith("error: grade-class runs each student's code in a box")
                .contains("bubblewrap (bwrap) is not installed", "apt-get install bubblewrap", "--no-sandbox");
        assertThat(other.resolve("c.csv")).doesNotExist();
    }

    /** Issue 34, item 2: the table's default place, the current folder, read-only: refused at once, before any student is graded. */
    @Test void aTableThatCannotBeWrittenIsRefusedBeforeAnyGrading(@TempDir Path dir) throws Exception {
        Path jars = Files.createDirectory(dir.resolve("jars"));
        StudentJars.compile(jars, "alice.jar", "my-builder", 2, null);
        try (ReadOnlyFolder ro = ReadOnlyFolder.make(dir, "ro")) {
            Process p = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-cp",
                    System.getProperty("java.class.path"), Main.class.getName(), "grade-class", jars.toString(), "-q")
                    .directory(ro.path().toFile()).start();
            String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            String err = new String(p.getErrorStream().readAllBytes(), StandardCharsets.UTF_8);
            assertThat(p.waitFor()).as(err).isEqualTo(Failure.USAGE);
            assertThat(err.strip()).isEqualTo("error: --csv class-grades.csv: permission denied (no file can be written in " + ro.path() + ")");
            assertThat(out).isEmpty();
        }
    }

    /** Issue 34, item 2: a table file that fails at the end (its folder made read-only meanwhile) is kept elsewhere, and said where. */
    @Test void aTableThatFailsAtTheEndIsKeptInATemporaryFile(@TempDir Path dir) throws Exception {
        ClassTable table = new ClassTable(List.of(StudentRow.failed("alice.jar", "Alice", "crashed: for the test", 1.5, "bubblewrap")), List.of());
        try (ReadOnlyFolder ro = ReadOnlyFolder.make(dir, "ro")) {
            Path csv = ro.path().resolve("class.csv");
            List<String> lost = ClassGradeCommand.save(table, csv, dir.resolve("class.md"));
            assertThat(lost).hasSize(1);
            assertThat(lost.get(0)).startsWith("error: " + csv + ": permission denied").contains("; the table is kept in ");
            Path kept = Path.of(lost.get(0).substring(lost.get(0).indexOf("kept in ") + "kept in ".length()));
            assertThat(Files.readString(kept)).isEqualTo(table.csv()).contains("alice.jar", "Alice");
            assertThat(Files.readString(dir.resolve("class.md"))).isEqualTo(table.markdown());
            Files.delete(kept);
        }
    }

    @Test void aFolderWithoutJarsIsOneLine(@TempDir Path dir) {
        CliRun run = CliRun.of("grade-class", dir.toString(), "--csv", dir.resolve("c.csv").toString());
        assertThat(run.code()).isEqualTo(Failure.USAGE);
        assertThat(run.err().strip()).isEqualTo("error: grade-class " + dir + ": the folder holds no .jar");
    }

    private static void jar(Path dir, String name, String student, String... classes) throws Exception {
        String builder = classes.length == 0 || classes[0].isEmpty() ? "" : T + classes[0];
        String[] helpers = new String[Math.max(0, classes.length - 1)];
        for (int i = 1; i < classes.length; i++) helpers[i - 1] = T + classes[i];
        PluginJars.student(dir, name, student, builder.isEmpty() ? new String[0] : new String[] {builder}, helpers);
    }

    /** The CSV's rows by file name, each a map from column to value. */
    static Map<String, Map<String, String>> rows(String csv) {
        String[] lines = csv.split("\n");
        List<String> head = org.kdtree.files.CsvFields.of(lines[0]);
        Map<String, Map<String, String>> rows = new HashMap<>();
        for (int i = 1; i < lines.length; i++) {
            List<String> f = org.kdtree.files.CsvFields.of(lines[i]);
            Map<String, String> row = new HashMap<>();
            for (int c = 0; c < head.size(); c++) row.put(head.get(c), f.get(c));
            rows.put(row.get("file"), row);
        }
        return rows;
    }
}
