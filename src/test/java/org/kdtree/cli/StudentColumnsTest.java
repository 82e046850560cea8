package org.kdtree.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.jar.Attributes;
import java.util.jar.JarEntry;
import java.util.jar.JarOutputStream;
import java.util.jar.Manifest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Issue 34, item 10: grade-class's student column from the jar (manifest, else the pom Maven put in it); first_failure whole in the CSV. */
class StudentColumnsTest {
    private static Path jar(Path dir, String name, String vendor, String groupId, String artifactId) throws Exception {
        Path jar = dir.resolve(name);
        Manifest m = new Manifest();
        m.getMainAttributes().put(Attributes.Name.MANIFEST_VERSION, "1.0");
        if (vendor != null) m.getMainAttributes().put(Attributes.Name.IMPLEMENTATION_VENDOR, vendor);
        try (OutputStream out = Files.newOutputStream(jar); JarOutputStream j = new JarOutputStream(out, m)) {
            j.putNextEntry(new JarEntry("META-INF/maven/" + groupId + "/" + artifactId + "/pom.properties"));
            j.write(("groupId=" + groupId + "\nartifactId=" + artifactId + "\nversion=1.0-SNAPSHOT\n").getBytes(StandardCharsets.UTF_8));
            j.closeEntry();
        }
        return jar;
    }

    @Test void theStudentIsTheManifestsVendorElseThePomsCoordinatesUnlessTheStartersOwnElseTheFileName(@TempDir Path dir) throws Exception {
        assertThat(StudentJvm.student(jar(dir, "a.jar", "Alice Martin", "course.kdtree", "my-builder"))).isEqualTo("Alice Martin");
        assertThat(StudentJvm.student(jar(dir, "b.jar", null, "edu.bob", "bob-builder"))).isEqualTo("edu.bob:bob-builder");
        assertThat(StudentJvm.student(jar(dir, "carol-durand.jar", null, "course.kdtree", "my-builder"))).isEqualTo("carol-durand");
        assertThat(StudentJvm.student(Files.writeString(dir.resolve("judy.jar"), "not a jar"))).isEqualTo("judy");
    }

    /** Issue 46, item 9: a jar built as root says Built-By: root; the class table named every such student "root". */
    @Test void theBuildMachinesLoginNamesNoStudent(@TempDir Path dir) throws Exception {
        Path jar = dir.resolve("dan.jar");
        Manifest m = new Manifest();
        m.getMainAttributes().put(Attributes.Name.MANIFEST_VERSION, "1.0");
        m.getMainAttributes().putValue("Built-By", "root");
        m.getMainAttributes().put(Attributes.Name.IMPLEMENTATION_VENDOR, "");
        try (OutputStream out = Files.newOutputStream(jar); JarOutputStream j = new JarOutputStream(out, m)) {
            j.putNextEntry(new JarEntry("builder/MyBuilder.class"));
            j.closeEntry();
        }
        assertThat(StudentJvm.student(jar)).isEqualTo("dan");
    }

    @Test void theStartersPomWritesTheDeclaredStudentIntoTheJarAndNeverTheLogin() throws Exception {
        String pom = Files.readString(Path.of("docs/assignment/template/pom.xml"));
        assertThat(pom).contains("<student></student>").contains("<Implementation-Vendor>${student}</Implementation-Vendor>")
                .doesNotContain("${user.name}");
    }

    @Test void aLongFirstFailureIsWholeInTheCsvAndShortenedInTheMarkdown() {
        String failure = "builder x: findPlane returned a plane outside the voxel " + "at depth 3 ".repeat(40) + "(the end)";
        String csv = "section,case,builder,result,a,b,c,d\ncontract,talk figures,x,\"FAIL: " + failure + "\",,,,\n"
                + "verdict,,x,FAIL: breaks the contract,,,,\n";
        StudentRow row = StudentRow.parse("x.jar", "X", csv, 1, "bubblewrap");
        assertThat(row.failure()).isEqualTo(failure);
        ClassTable table = new ClassTable(List.of(row), List.of());
        assertThat(table.csv()).contains("(the end)").doesNotContain("...");
        assertThat(table.markdown()).doesNotContain("(the end)").contains("...");
    }
}
