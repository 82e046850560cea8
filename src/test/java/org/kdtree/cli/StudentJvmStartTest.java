package org.kdtree.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.File;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.jar.JarEntry;
import java.util.jar.JarOutputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kdtree.check.CourseScenes;
import org.kdtree.limits.Deadlines;
import org.kdtree.testing.StudentJars;

/**
 * Issue 44, item 6: a class's students' JVMs start cheaply (C1 only, the serial collector, the
 * library's classes mapped from an archive made once for the class), and a student's build
 * times are compared with the SAH's timed in a JVM started the same way.
 */
class StudentJvmStartTest {
    @Test void aClassArchivesTheLibrarysClassesOnceAndEachStudentsJvmMapsThem(@TempDir Path dir) throws Exception {
        gradeAClassFromAJar(dir, "--no-sandbox");
    }

    /** In the box the archive is a bind of its own, readable by the box's user (nobody, for a root teacher). */
    @Test void inTheBoxToo(@TempDir Path dir) throws Exception {
        BoxTests.assumeABoxCanBeMade();
        gradeAClassFromAJar(dir);
    }

    /** Tests run the library from a folder of classes, which the JVM does not archive: the class is graded from a jar of them, as users run it. */
    private static void gradeAClassFromAJar(Path dir, String... options) throws Exception {
        Path lib = libraryJar(dir.resolve("kdtree.jar"));
        Path jars = Files.createDirectory(dir.resolve("class"));
        StudentJars.compile(jars, "alice.jar", "my-builder", 2, null);
        StudentJars.compile(jars, "bob.jar", "my-builder", 3, null);
        List<String> classPath = new ArrayList<>(List.of(lib.toString()));
        for (String e : StudentJvm.classPath().split(File.pathSeparator)) if (Files.isRegularFile(Path.of(e))) classPath.add(e);
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-cp", String.join(File.pathSeparator, classPath), Main.class.getName(), "grade-class", jars.toString(), "-q",
                "--csv", dir.resolve("c.csv").toString(), "--markdown", dir.resolve("c.md").toString(), "--student-heap", "128"));
        cmd.addAll(List.of(options));
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertThat(p.waitFor(240, TimeUnit.SECONDS)).isTrue();
        assertThat(p.exitValue()).as(out).isZero();
        assertThat(out).contains("the students' JVMs: C1 compiler only, serial collector, "
                + "the library's classes mapped from an archive made for the class").doesNotContain("warning");
        assertThat(Files.readString(dir.resolve("c.csv"))).contains("alice.jar", "bob.jar").doesNotContain("FAIL");
    }

    /** The check the class's archive passes before it is used: a JVM told it must map an archive fails on one it cannot use. */
    @Test void aRequiredArchiveTheJvmCannotUseFailsAndOneNotRequiredIsPassedOver(@TempDir Path dir) throws Exception {
        Path jar = StudentJars.compile(dir, "alice.jar", "my-builder", 2, null);
        Path garbage = Files.writeString(dir.resolve("library.jsa"), "not an archive");
        StudentJvm plain = new StudentJvm(Deadlines.GRADE, 120, 128, null);
        assertThat(plain.with(new JvmStart(garbage, true)).run(jar).report()).isNull();
        assertThat(plain.with(new JvmStart(garbage, false)).run(jar).report()).isNotNull();
    }

    /** The SAH's build time on each course scene, as a student's JVM measures it: what a student's times are compared with. */
    @Test void theSahIsTimedInAJvmStartedAsTheStudentsAre(@TempDir Path dir) throws Exception {
        StudentJvm jvm = new StudentJvm(Deadlines.GRADE, 120, 128, null).withReference();
        assertThat(jvm.sahMillis()).containsOnlyKeys(CourseScenes.all().stream().map(CourseScenes.Named::name).toList());
        assertThat(jvm.sahMillis().values()).allSatisfy(ms -> assertThat(ms).isPositive());
        Path jar = StudentJars.compile(dir, "alice.jar", "my-builder", 2, null);
        List<GradeCommand.Row> rows = jvm.run(jar).report().rows();
        int per = GradeCommand.BUILT_INS.size() + 1, sah = 1 + GradeCommand.BUILT_INS.indexOf("sah");
        for (int i = 0; i < rows.size(); i += per)
            assertThat(rows.get(i + sah).ms()).as(rows.get(i).scene()).isEqualTo(jvm.sahMillis().get(rows.get(i).scene()));
    }

    private static Path libraryJar(Path jar) throws Exception {
        Path classes = Path.of(Main.class.getProtectionDomain().getCodeSource().getLocation().toURI());
        try (OutputStream o = Files.newOutputStream(jar); JarOutputStream j = new JarOutputStream(o); var files = Files.walk(classes)) {
            for (Path f : files.filter(Files::isRegularFile).toList()) {
                j.putNextEntry(new JarEntry(classes.relativize(f).toString().replace(File.separatorChar, '/')));
                j.write(Files.readAllBytes(f));
            }
        }
        return jar;
    }
}
