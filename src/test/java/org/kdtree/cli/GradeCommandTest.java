package org.kdtree.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kdtree.spec.Builders;
import org.kdtree.testing.PlaneOutsideBuilder;
import org.kdtree.testing.PluginJars;

/** {@code grade}: the course example honours the contract but not the quality tier; a broken plug-in fails it. */
class GradeCommandTest {
    @TempDir Path dir;

    /** Other tests build with every registered builder: the broken plug-in must not stay. */
    @AfterEach void forgetThePlugIn() {
        Builders.remove("plane-outside");
    }

    @Test void theCourseExampleIsCorrectButFailsTheQualityTier() throws Exception {
        Path md = dir.resolve("half.md");
        CliRun r = CliRun.of("grade", "--builder", "centre-midpoint", "-o", md.toString());
        assertThat(r.code()).as(r.err()).isZero();
        assertThat(r.out()).contains("talk figures                                 pass")
                .contains("any random 2-D scene (30 tries)              pass")
                .contains("planes separate something                    pass")
                .contains("leaves stop before the depth cap             pass")
                .contains("expected cost at most the median plane's     FAIL  centre-midpoint: on corner clusters,"
                        + " the tree's expected SAH cost is 601.86, 5.02 times the median-plane builder's 119.84")
                .contains("verdict: CORRECT: honours the contract (18 of 18 checks); fails quality:"
                        + " expected cost at most the median plane's; cheaper than median-plane on 2 of 5 scenes");
        assertThat(r.out()).containsPattern("cornell-box +centre-midpoint +1242\\.68 +115037 +24 ");
        assertThat(Files.readString(md)).startsWith("# Grade: centre-midpoint").contains("| cornell-box | sah | 427.99 |");
    }

    @Test void aBrokenBuilderFromAPluginJarFailsTheContract() throws Exception {
        Path jar = PluginJars.listing(dir, "student.jar", PlaneOutsideBuilder.class.getName());
        Path csv = dir.resolve("grade.csv");
        CliRun r = CliRun.of("--plugin", jar.toString(), "grade", "--builder", "plane-outside", "-o", csv.toString());
        assertThat(r.code()).as(r.err()).isEqualTo(1);
        assertThat(r.out()).contains("talk figures                                 FAIL  builder plane-outside: findPlane chose x0 = ")
                .contains("outside the voxel")
                .contains("mixed 2-D shapes                             FAIL  builder plane-outside: findPlane chose x0 = ")
                .contains("uniform triangles                            FAIL  the same failure as mixed 2-D shapes above")
                .contains("verdict: FAIL: breaks the contract (")
                .doesNotContain("quality (course scenes)");
        assertThat(Files.readAllLines(csv).get(0)).isEqualTo("section,item,builder,result,expected_cost,nodes,depth,build_ms");
        assertThat(Files.readString(csv)).contains("verdict,,\"plane-outside\",\"FAIL: breaks the contract");
    }

    @Test void theObjectMediansPlanesOnTheFaceAreFlagged() {
        CliRun r = CliRun.of("grade", "-b", "object-median");
        assertThat(r.out()).contains("planes separate something                    FAIL  object-median: on cornell-box, 56 split planes");
    }

    @Test void theSahIsGood() {
        CliRun r = CliRun.of("grade", "-b", "sah");
        assertThat(r.code()).as(r.err()).isZero();
        assertThat(r.out()).contains("verdict: GOOD: honours the contract (18 of 18 checks); passes every quality check;"
                + " cheaper than median-plane on 5 of 5 scenes");
    }

    @Test void mistakesCostOneLine() throws Exception {
        assertThat(CliRun.of("grade", "--builder", "nope").err()).startsWith("error: unknown builder 'nope' (known: sah, ");
        assertThat(CliRun.of("grade", "--builder", "sah", "-o", dir.resolve("x.txt").toString()).err())
                .contains("write a .md (Markdown) or .csv report");
        CliRun missing = CliRun.of("--plugin", dir.resolve("none.jar").toString(), "stats", "scenes:talk-figures");
        assertThat(missing.code()).isEqualTo(Failure.USAGE);
        assertThat(missing.err()).isEqualTo("error: --plugin " + dir.resolve("none.jar") + ": no such jar or folder" + System.lineSeparator());
        Path empty = Files.createDirectory(dir.resolve("plugins"));
        assertThat(CliRun.of("--plugin", empty.toString(), "stats", "scenes:talk-figures").err())
                .contains("no builder listed in META-INF/services/org.kdtree.kdtree.KdTreeBuilder (the folder holds no .jar)");
    }
}
