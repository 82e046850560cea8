package org.kdtree.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kdtree.spec.Builders;
import org.kdtree.testing.StudentJars;

/**
 * Issue 34, item 9: a plug-in variant whose builder fails is left out of the trade-off study with
 * one line; the others are measured, and the CSV and chart are written in place of the old ones.
 */
class TradeoffFaultyVariantTest {
    @AfterEach void forgetThePlugIn() {
        Builders.remove("thrower");
    }

    @Test void aFailingPlugInVariantIsSkippedAndTheStudyFinishes(@TempDir Path dir) throws Exception {
        Path jar = StudentJars.compile(dir, "thrower.jar", "thrower", 2, "throw new IllegalStateException(\"no plane for you\");");
        Path csv = Files.writeString(dir.resolve("t.csv"), "an old study\n"), png = dir.resolve("t.png");
        CliRun run = CliRun.of("--plugin", jar.toString(), "tradeoff", "scenes/clustered-spheres.obj", "--quick", "-b", "thrower",
                "--ray-count", "2000", "--counted-rays", "1000", "--runs", "1", "--csv", csv.toString(), "--chart", png.toString(), "-q");
        assertThat(run.code()).as(run.err()).isZero();
        assertThat(run.out()).containsPattern("(?m)^thrower +skipped: builder thrower: findPlane threw IllegalStateException")
                .contains("wrote " + csv + " and " + png)
                .contains("skipped 1 variant whose builder failed (not in the CSV or the chart): thrower");
        String table = Files.readString(csv);
        assertThat(table).doesNotContain("an old study", "thrower").contains("median-plane", "bvh");
        assertThat(png).isNotEmptyFile();
        assertThat(dir.resolve("t.csv.partial")).doesNotExist();
    }
}
