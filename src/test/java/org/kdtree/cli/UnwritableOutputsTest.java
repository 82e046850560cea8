package org.kdtree.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kdtree.testing.ReadOnlyFolder;

/**
 * Issue 34, item 4: an output a command cannot write (in a read-only folder, or a folder given
 * as the file) is one line naming the user's file and why, before any work: no temporary file's
 * name, no build, no rendering.
 */
class UnwritableOutputsTest {
    @TempDir Path dir;

    /** Each command with {@code OUT} where its output goes; the option that names it. */
    private List<String[]> commands(Path out, Path rays) {
        String o = out.toString();
        return List.of(
                new String[] {"-o", "render", "scenes:cornell-box", "-o", o + ".png", "-q"},
                new String[] {"--hits", "raycast", "scenes/clustered-spheres.obj", "--rays", rays.toString(), "--hits", o + ".hits", "-q"},
                new String[] {"--csv", "tradeoff", "scenes/clustered-spheres.obj", "--csv", o + ".csv", "--chart", o + ".png", "-q"},
                new String[] {"--csv", "knn-study", "--generate", "uniform", "--k", "4", "--csv", o + ".csv", "--chart", o + ".png", "-q"},
                new String[] {"-o", "grade", "-b", "sah", "-o", o + ".md", "-q"});
    }

    @Test void anOutputInAReadOnlyFolderIsNamedWithPermissionDeniedBeforeAnyWork() throws Exception {
        Path rays = Files.writeString(dir.resolve("rays.txt"), "0 0 -10 0 0 1\n");
        try (ReadOnlyFolder ro = ReadOnlyFolder.make(dir, "ro")) {
            for (String[] c : commands(ro.path().resolve("out"), rays)) {
                String option = c[0];
                String[] args = java.util.Arrays.copyOfRange(c, 1, c.length);
                long t0 = System.nanoTime();
                CliRun run = CliRun.of(args);
                double seconds = (System.nanoTime() - t0) / 1e9;
                String file = args[java.util.Arrays.asList(args).indexOf(option) + 1];
                assertThat(run.code()).as(String.join(" ", args) + ": " + run.err()).isEqualTo(Failure.USAGE);
                assertThat(run.err().strip()).as(args[0])
                        .isEqualTo("error: " + option + " " + file + ": permission denied (no file can be written in " + ro.path() + ")");
                assertThat(run.out()).as(args[0] + " did work before refusing").isEmpty();
                assertThat(seconds).as(args[0]).isLessThan(5);
            }
            try (var left = Files.list(ro.path())) {
                assertThat(left).isEmpty();
            }
        }
    }

    @Test void aFolderGivenAsTheOutputFileIsNamedAsAFolder() throws Exception {
        Path rays = Files.writeString(dir.resolve("rays.txt"), "0 0 -10 0 0 1\n");
        Path folder = Files.createDirectory(dir.resolve("results.hits"));
        CliRun run = CliRun.of("raycast", "scenes/clustered-spheres.obj", "--rays", rays.toString(), "--hits", folder.toString(), "-q");
        assertThat(run.code()).isEqualTo(Failure.USAGE);
        assertThat(run.err().strip()).isEqualTo("error: --hits " + folder + ": is a folder, not a file; give a file name");
        for (String ext : List.of(".csv", ".md")) {
            Path f = Files.createDirectory(dir.resolve("grade" + ext));
            CliRun grade = CliRun.of("grade", "-b", "sah", "-o", f.toString(), "-q");
            assertThat(grade.err().strip()).isEqualTo("error: -o " + f + ": is a folder, not a file; give a file name");
            assertThat(grade.out()).isEmpty();
        }
    }
}
