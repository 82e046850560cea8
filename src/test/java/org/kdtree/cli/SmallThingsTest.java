package org.kdtree.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Issue 34, item 11: the smaller things a newcomer trips on, each as a first-day user would expect. */
class SmallThingsTest {
    @TempDir Path dir;

    @Test void anEmptyObjIsRefusedByStatsNotCountedAsZeroPrimitives() throws Exception {
        Path empty = Files.writeString(dir.resolve("empty.obj"), "");
        CliRun r = CliRun.of("stats", empty.toString());
        assertThat(r.code()).isEqualTo(Failure.USAGE);
        assertThat(r.err().strip()).isEqualTo("error: " + empty + ": no triangles (no 'f' lines): not an OBJ mesh, or an empty one");
    }

    @Test void aCommentAfterAFaceIsRead() throws Exception {
        Path obj = Files.writeString(dir.resolve("c.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3 # a comment\n");
        CliRun r = CliRun.of("stats", obj.toString());
        assertThat(r.code()).as(r.err()).isZero();
        assertThat(r.out()).contains("(1 primitive, 3-D)");
    }

    @Test void aFolderGivenAsAFileReadsTheSameInEveryCommand() throws Exception {
        Path folder = Files.createDirectory(dir.resolve("data.obj"));
        Path pts = Files.writeString(dir.resolve("p.csv"), "0,0\n1,1\n");
        String[][] runs = {
            {"SCENE", "stats", folder.toString()},
            {"MESH", "raycast", folder.toString()},
            {"MESH", "tradeoff", folder.toString(), "--csv", dir.resolve("t.csv").toString(), "--chart", dir.resolve("t.png").toString()},
            {"POINTS", "knn", folder.toString(), "--queries", pts.toString(), "--k", "1", "--out", dir.resolve("o.csv").toString()},
            {"--queries", "knn", pts.toString(), "--queries", folder.toString(), "--k", "1", "--out", dir.resolve("o.csv").toString()},
            {"POINTS", "knn-study", folder.toString(), "--queries", pts.toString(), "--k", "1", "--csv", dir.resolve("s.csv").toString(),
                "--chart", dir.resolve("s.png").toString()},
        };
        for (String[] run : runs) {
            CliRun r = CliRun.of(java.util.Arrays.copyOfRange(run, 1, run.length));
            assertThat(r.code()).as(String.join(" ", run)).isEqualTo(Failure.USAGE);
            assertThat(r.err().strip()).as(run[1]).isEqualTo("error: " + run[0] + " " + folder + ": is a folder, not a file");
        }
    }

    /** Item 5: a bundled scene opens through the reader that fits it; raycast and tradeoff took none ("give an OBJ file" on the bundled OBJ). */
    @Test void raycastAndTradeoffTakeTheBundledMeshAsStatsDoes() throws Exception {
        CliRun r = CliRun.of("raycast", "scenes:clustered-spheres", "-b", "bvh", "--runs", "1", "--warmup", "0");
        assertThat(r.code()).as(r.err()).isZero();
        assertThat(r.out()).startsWith("kdtree-bvh clustered-spheres 10370 ");
        Path csv = dir.resolve("t.csv");
        r = CliRun.of("tradeoff", "scenes:clustered-spheres", "--variants", "bvh", "--runs", "1", "--ray-count", "1000",
                "--counted-rays", "100", "--csv", csv.toString(), "--chart", dir.resolve("t.png").toString(), "-q");
        assertThat(r.code()).as(r.err()).isZero();
        assertThat(r.out()).contains("scene: clustered-spheres (10370 triangles)");
        assertThat(Files.readAllLines(csv)).hasSize(2);
        r = CliRun.of("raycast", "scenes:talk-figures");
        assertThat(r.err().strip()).isEqualTo("error: scenes:talk-figures: raycast traces rays through a triangle mesh; "
                + "give an OBJ file (bundled: scenes:clustered-spheres)");
    }

    /** A missing file reads "no such file" in every command, whatever its name (stats said "unknown file type", render and raycast named its kind). */
    @Test void aMissingFileIsNoSuchFileWhateverItsName() {
        for (String name : new String[] {"nothing", "notes.txt", "scene.obj"}) {
            Path missing = dir.resolve(name);
            for (String command : new String[] {"stats", "render", "raycast"}) {
                CliRun r = CliRun.of(command, missing.toString(), "-q");
                assertThat(r.code()).as(command + " " + name).isEqualTo(Failure.USAGE);
                assertThat(r.err().strip()).as(command + " " + name).isEqualTo("error: " + missing + ": no such file");
            }
        }
    }

    /** grade-class given a file, a student's jar say, said "no such folder" of a file that is there. */
    @Test void gradeClassGivenAFileSaysItIsAFile() throws Exception {
        Path jar = Files.writeString(dir.resolve("student.jar"), "");
        CliRun r = CliRun.of("grade-class", jar.toString(), "--no-sandbox");
        assertThat(r.code()).isEqualTo(Failure.USAGE);
        assertThat(r.err().strip()).isEqualTo("error: grade-class " + jar + ": is a file, not a folder; give the folder of the "
                + "students' jars (one student's jar: grade --student-jar JAR)");
        r = CliRun.of("grade-class", dir.resolve("none").toString(), "--no-sandbox");
        assertThat(r.err().strip()).isEqualTo("error: grade-class " + dir.resolve("none") + ": no such folder");
    }

    /** tradeoff --variants with one name mistyped measured the others and left it out without a word. */
    @Test void aMistypedVariantIsRefusedNotLeftOut() {
        Path csv = dir.resolve("t.csv");
        CliRun r = CliRun.of("tradeoff", "scenes:clustered-spheres", "--variants", "bvh,sah-fats", "--csv", csv.toString(),
                "--chart", dir.resolve("t.png").toString(), "-q");
        assertThat(r.code()).isEqualTo(Failure.USAGE);
        assertThat(r.err().strip()).startsWith("error: --variants: no variant named sah-fats; known: median-plane, object-median, ")
                .contains(", sah-fast, ").doesNotContain("[");
        assertThat(csv).as("refused before any work").doesNotExist();
    }

    @Test void renderIntoALogSaysWhatItRendersBeforeItIsDone() throws Exception {
        Path png = dir.resolve("c.png");
        CliRun r = CliRun.of("render", "scenes:cornell-box", "-o", png.toString(), "--spp", "1", "--width", "64", "--height", "48");
        assertThat(r.code()).as(r.err()).isZero();
        assertThat(r.out()).startsWith("rendering scenes:cornell-box: 64 x 48, 1 sample per pixel, into " + png + "\n");
        assertThat(r.out().indexOf("rendering scenes:cornell-box")).isLessThan(r.out().indexOf("build time"));
    }

    @Test void knnStudyOnATinyInputWarnsThatItsSpeedsAreNoise() throws Exception {
        CliRun r = CliRun.of("knn-study", "--generate", "uniform", "--n", "200", "--query-count", "10", "--k", "3", "--runs", "1",
                "--csv", dir.resolve("s.csv").toString(), "--chart", dir.resolve("s.png").toString(), "-q");
        assertThat(r.code()).as(r.err()).isZero();
        assertThat(r.out()).containsPattern("warning: a timed pass took only [0-9.]+ ms \\(10 queries\\): too short to time well");
    }

    @Test void theReadmeGivesTheQuickBenchmarkCommandAndSaysTheWholeRunTakesHours() throws Exception {
        String readme = Files.readString(Path.of("README.md"));
        assertThat(readme).contains("-f 1 -wi 1 -i 2 -w 1s -r 1s").contains("with no pattern runs every benchmark for hours");
    }
}
