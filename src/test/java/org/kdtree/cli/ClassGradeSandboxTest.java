package org.kdtree.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.File;
import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.stream.Stream;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kdtree.testing.IntrudingBuilder;
import org.kdtree.testing.PluginJars;

/**
 * grade-class's box (issue 35): a class of students' jars that try, from terminate or findPlane,
 * what a student should not be able to do to the teacher's machine or to its own grade. After
 * one grade-class run of them all: nothing outside the box changed (the class folder and the
 * teacher's folder listed and hashed, the home folder and /tmp without the intruder's file, no
 * connection made), each row's verdict is the one its trees earn (that of a jar with the same
 * trees that tries nothing), and the row says what the box stopped where it can tell.
 */
class ClassGradeSandboxTest {
    private static final String SECRET = "the exam's answers: 42";

    @TempDir
    static Path dir;
    private static Path classFolder, teacher;
    private static final Path HOME = Path.of(System.getProperty("user.home")), TMP = Path.of("/tmp");
    private static Map<String, String> classBefore, teacherBefore, tmpReportBefore;
    private static Map<String, Map<String, String>> rows;
    private static String table;
    private static CliRun run;
    private static ServerSocket server;
    private static final AtomicInteger CONNECTIONS = new AtomicInteger();

    @BeforeAll static void gradeAClassOfIntruders() throws Exception {
        BoxTests.assumeABoxCanBeMade();
        assertThat(Files.exists(HOME.resolve(IntrudingBuilder.MARKER))).as("a marker left by an earlier run").isFalse();
        assertThat(Files.exists(TMP.resolve(IntrudingBuilder.MARKER))).as("a marker left by an earlier run").isFalse();
        classFolder = Files.createDirectory(dir.resolve("class"));
        teacher = Files.createDirectory(dir.resolve("teacher"));
        Files.writeString(teacher.resolve("secret.txt"), SECRET);
        server = new ServerSocket(0, 50, InetAddress.getLoopbackAddress());
        server.setSoTimeout(200);
        Thread accept = new Thread(ClassGradeSandboxTest::accept, "intruder-listener");
        accept.setDaemon(true);
        accept.start();

        jar("control.jar", "terminate", "", "", false);
        jar("leaves.jar", "terminate", "", "", true);
        jar("write-home.jar", "terminate", "write", HOME + ";" + teacher + ";~", false);
        jar("write-class.jar", "findPlane", "write", classFolder.toString(), false);
        jar("write-tmp.jar", "terminate", "write", TMP.toString(), false);
        jar("read.jar", "findPlane", "read", teacher.resolve("secret.txt").toString(), false);
        jar("delete.jar", "terminate", "delete", classFolder.resolve("control.jar").toString(), false);
        jar("socket.jar", "findPlane", "socket", Integer.toString(server.getLocalPort()), false);
        jar("process.jar", "terminate", "process", teacher.toString(), false);
        jar("threads.jar", "findPlane", "threads", "", false);
        jar("fill.jar", "terminate", "fill", "", false);
        jar("forge-files.jar", "terminate", "forge-files", classFolder + ";" + TMP, true); // every node a leaf: no findPlane
        jar("forge-stdout.jar", "terminate", "forge-stdout", "", true);
        jar("forge-hook.jar", "terminate", "forge-hook", "", true);
        classBefore = snapshot(classFolder);
        teacherBefore = snapshot(teacher);
        tmpReportBefore = Files.exists(TMP.resolve("grade.csv")) ? Map.of("grade.csv", hash(TMP.resolve("grade.csv"))) : Map.of();

        Path csv = dir.resolve("class.csv"), md = dir.resolve("class.md");
        run = CliRun.of("grade-class", classFolder.toString(), "--csv", csv.toString(), "--markdown", md.toString(), "-q",
                "--jobs", "2", "--student-heap", "128", "--student-deadline", "120", "--call-deadline", "20", "--build-deadline", "30");
        assertThat(run.code()).as(run.err()).isZero();
        table = Files.readString(md);
        System.out.println(table);
        rows = ClassGradeCommandTest.rows(Files.readString(csv, StandardCharsets.UTF_8));
    }

    @AfterAll static void closeListener() throws IOException {
        if (server != null) server.close();
    }

    @Test void nothingOutsideTheBoxChanged() throws Exception {
        assertThat(snapshot(classFolder)).as("the class folder, listed and hashed").isEqualTo(classBefore);
        assertThat(snapshot(teacher)).as("the teacher's folder, listed and hashed").isEqualTo(teacherBefore);
        assertThat(HOME.resolve(IntrudingBuilder.MARKER)).doesNotExist();
        assertThat(TMP.resolve(IntrudingBuilder.MARKER)).doesNotExist();
        Map<String, String> tmpReport = Files.exists(TMP.resolve("grade.csv")) ? Map.of("grade.csv", hash(TMP.resolve("grade.csv"))) : Map.of();
        assertThat(tmpReport).as("/tmp/grade.csv").isEqualTo(tmpReportBefore);
        Thread.sleep(300); // the listener's last poll
        assertThat(CONNECTIONS.get()).as("connections to the teacher's machine").isZero();
        assertThat(table).doesNotContain(SECRET);
    }

    @Test void everyRowHasTheVerdictItsTreesEarn() {
        assertThat(rows).hasSize(14);
        String sound = rows.get("control.jar").get("verdict"), leaves = rows.get("leaves.jar").get("verdict");
        assertThat(sound).as("the control: " + rows.get("control.jar")).isIn("CORRECT", "GOOD");
        assertThat(leaves).as("every node a leaf: " + rows.get("leaves.jar")).isEqualTo("CORRECT");
        for (String jar : List.of("write-home.jar", "write-class.jar", "write-tmp.jar", "read.jar", "delete.jar", "socket.jar",
                "process.jar", "threads.jar", "fill.jar"))
            assertThat(rows.get(jar).get("verdict")).as(jar + ": " + rows.get(jar)).isEqualTo(sound);
        for (String jar : List.of("forge-files.jar", "forge-hook.jar")) {
            assertThat(rows.get(jar).get("verdict")).as(jar + ": " + rows.get(jar)).isEqualTo(leaves);
            assertThat(rows.get(jar).get("quality_failed")).as(jar).isEqualTo(rows.get("leaves.jar").get("quality_failed")).isNotEmpty();
        }
        for (Map<String, String> r : rows.values()) assertThat(r.get("box")).isEqualTo("bubblewrap");
    }

    @Test void aReportForgedInTheChannelIsAFaultNamedInTheRow() {
        Map<String, String> forged = rows.get("forge-stdout.jar");
        assertThat(forged.get("verdict")).isEqualTo("FAIL");
        assertThat(forged.get("problem")).contains("its report does not match the checks made of it");
        assertThat(rows.get("forge-hook.jar").get("problem")).contains("bytes into its report channel after the report: ignored");
    }

    @Test void theRowSaysWhatTheBoxStopped() {
        assertThat(problem("write-home.jar")).contains("the box stopped", "access to a file outside the box");
        assertThat(problem("write-class.jar")).contains("access to a file outside the box");
        assertThat(problem("read.jar")).contains("access to a file outside the box");
        assertThat(problem("delete.jar")).contains("access to a file outside the box");
        assertThat(problem("socket.jar")).contains("a connection (no network)");
        assertThat(problem("process.jar")).contains("access to a file outside the box");
        assertThat(problem("threads.jar")).contains("a thread or process beyond the bound of " + StudentBox.TASKS);
        assertThat(problem("fill.jar")).contains("its scratch folder is full (" + StudentBox.SCRATCH_MB + " MB)");
        assertThat(problem("control.jar")).doesNotContain("the box stopped");
    }

    @Test void gradeGivenAStudentsJarRunsItInTheSameBox(@TempDir Path other) throws Exception {
        Path jar = Files.copy(classFolder.resolve("write-home.jar"), other.resolve("write-home.jar"));
        Map<String, String> before = snapshot(other);
        CliRun one = CliRun.of("grade", "--student-jar", jar.toString(), "-q", "--call-deadline", "20");
        assertThat(one.code()).as(one.err()).isZero();
        assertThat(one.out()).contains("verdict: " + rows.get("control.jar").get("verdict"))
                .contains("the student's JVM: the box stopped access to a file outside the box");
        assertThat(snapshot(other)).isEqualTo(before);
        assertThat(HOME.resolve(IntrudingBuilder.MARKER)).doesNotExist();
        CliRun notAJar = CliRun.of("grade", "--student-jar", Files.writeString(other.resolve("notes.jar"), "notes").toString(), "-q");
        assertThat(notAJar.code()).isEqualTo(Failure.USAGE);
        assertThat(notAJar.err().strip()).isEqualTo("error: grade notes.jar: not graded: not a jar (zip) file");   // issue 46, item 9: the prefix of every error
    }

    @Test void withoutTheBoxTheSameJarWritesIntoTheTeachersFolderAndEveryRowSaysSo(@TempDir Path other) throws Exception {
        Path jars = Files.createDirectory(other.resolve("class")), home = Files.createDirectory(other.resolve("teacher"));
        PluginJars.student(jars, "write.jar", "W", new String[] {IntrudingBuilder.class.getName()}, new String[0],
                Map.of("intrusion.properties", "from=terminate\naction=write\ntarget=" + home + "\n"));
        CliRun unboxed = CliRun.of("grade-class", jars.toString(), "--no-sandbox", "--csv", other.resolve("c.csv").toString(),
                "--markdown", other.resolve("c.md").toString(), "-q", "--jobs", "1", "--student-heap", "128");
        assertThat(unboxed.code()).as(unboxed.err()).isZero();
        assertThat(home.resolve(IntrudingBuilder.MARKER)).as("the attempt the box stops, unboxed").exists();
        assertThat(Files.readString(other.resolve("c.md"))).contains("not boxed (--no-sandbox)");
        assertThat(ClassGradeCommandTest.rows(Files.readString(other.resolve("c.csv"))).get("write.jar").get("box")).isEqualTo("none (--no-sandbox)");
    }

    private static String problem(String jar) {
        return rows.get(jar).get("problem");
    }

    private static void jar(String name, String from, String action, String target, boolean leaves) throws IOException {
        PluginJars.student(classFolder, name, name.replace(".jar", ""), new String[] {IntrudingBuilder.class.getName()}, new String[0],
                Map.of("intrusion.properties", "from=" + from + "\naction=" + action + "\ntarget=" + target + "\nleaves=" + leaves + "\n"));
    }

    private static void accept() {
        while (!server.isClosed()) {
            try (Socket s = server.accept()) {
                CONNECTIONS.incrementAndGet();
            } catch (SocketTimeoutException again) {
                // poll
            } catch (IOException closed) {
                return;
            }
        }
    }

    /** Every file below {@code root}, by relative path, with its SHA-256. */
    static Map<String, String> snapshot(Path root) throws IOException {
        Map<String, String> out = new TreeMap<>();
        try (Stream<Path> files = Files.walk(root)) {
            for (Path f : files.toList())
                out.put(root.relativize(f).toString() + (Files.isDirectory(f) ? File.separator : ""), Files.isDirectory(f) ? "" : hash(f));
        }
        return out;
    }

    static String hash(Path f) throws IOException {
        try {
            return HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256").digest(Files.readAllBytes(f)));
        } catch (java.security.NoSuchAlgorithmException e) {
            throw new IllegalStateException(e);
        }
    }
}
