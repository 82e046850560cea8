package org.kdtree.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kdtree.testing.StudentJars;

/** Issue 34, item 1: two students' jars that both name their builder "my-builder" are refused, naming both jars. */
class DuplicateBuilderNamesTest {
    @org.junit.jupiter.api.AfterEach void forgetThePlugIn() {
        org.kdtree.spec.Builders.remove("my-builder");
    }

    @Test void aFolderWithTwoJarsOfOneBuilderNameIsRefusedNamingBoth(@TempDir Path dir) throws Exception {
        Path folder = Files.createDirectory(dir.resolve("class"));
        Path alice = StudentJars.compile(folder, "alice.jar", "my-builder", 2, null);
        Path bob = StudentJars.compile(folder, "bob.jar", "my-builder", 8, null);
        CliRun run = CliRun.of("--plugin", folder.toString(), "grade", "-b", "my-builder", "-o", dir.resolve("g.csv").toString());
        assertThat(run.code()).isEqualTo(Failure.USAGE);
        assertThat(run.err().strip()).isEqualTo("error: --plugin " + folder + ": two jars register the builder 'my-builder': "
                + alice + " and " + bob + "; keep one of them, or give one builder another name()");
        assertThat(dir.resolve("g.csv")).doesNotExist();
    }

    @Test void twoPluginOptionsGivingOneBuilderNameAreRefusedNamingBoth(@TempDir Path dir) throws Exception {
        Path alice = StudentJars.compile(Files.createDirectory(dir.resolve("a")), "student.jar", "my-builder", 2, null);
        Path bob = StudentJars.compile(Files.createDirectory(dir.resolve("b")), "student.jar", "my-builder", 8, null);
        CliRun run = CliRun.of("--plugin", alice.toString(), "--plugin", bob.toString(), "stats", "scenes:talk-figures", "-b", "my-builder");
        assertThat(run.code()).isEqualTo(Failure.USAGE);
        assertThat(run.err().strip()).isEqualTo("error: --plugin: two plug-ins register the builder 'my-builder': " + alice + " and "
                + bob + "; keep one of them, or give one builder another name()");
    }

    @Test void oneJarOfThatNameIsGraded(@TempDir Path dir) throws Exception {
        Path folder = Files.createDirectory(dir.resolve("class"));
        StudentJars.compile(folder, "alice.jar", "my-builder", 2, null);
        CliRun run = CliRun.of("--plugin", folder.toString(), "stats", "scenes:talk-figures", "-b", "my-builder");
        assertThat(run.code()).as(run.err()).isZero();
        assertThat(run.out()).contains("my-builder");
    }
}
