package org.kdtree.limits;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.kdtree.accel.CostModel;
import org.kdtree.io.PrimitivesReader;
import org.kdtree.kdtree.SahBuilder;
import org.kdtree.scene.GeometryBuilder;

class LimitsTest {
    @Test void eachLimitAllowsItsEndsAndRejectsJustBeyondThem() {
        for (Limit l : Limits.ALL) {
            assertThat(l.allows(l.min())).as(l.title()).isTrue();
            assertThat(l.allows(l.max())).as(l.title()).isTrue();
            double below = l.integer() ? l.min() - 1 : Math.nextDown(l.min());
            double above = l.integer() ? l.max() + 1 : Math.nextUp(l.max());
            assertThat(l.allows(below)).as(l.title()).isFalse();
            assertThat(l.allows(above)).as(l.title()).isFalse();
            assertThat(l.allows(Double.NaN)).as(l.title()).isFalse();
            if (l.integer()) assertThat(l.allows(l.min() + 0.5)).as(l.title() + ": a fraction").isFalse();
        }
    }

    @Test void aRejectionNamesWhereTheRangeTheNoteAndTheValue() {
        assertThatThrownBy(() -> Limits.MAX_DEPTH.check("--max-depth", 65))
                .hasMessage("--max-depth must be between -1 and 64 (-1 = auto: 8 + 1.3 log2 N for a kd-tree, 64 for a BVH), got 65");
        assertThatThrownBy(() -> Limits.LAMBDA.check("lambda", 0.0)).hasMessage("lambda must be between 0.01 and 1, got 0");
    }

    @Test void theApiRefusesWhatTheCommandLineAndTheFilesRefuse() {
        assertThatThrownBy(() -> new SahBuilder().threads(257)).hasMessage("threads must be between 1 and 256, got 257");
        assertThatThrownBy(() -> new SahBuilder().maxDepth(65)).hasMessageStartingWith("Kmaxdepth must be between -1 and 64");
        assertThatThrownBy(() -> new SahBuilder().lambda(0)).hasMessageContaining("must be between 0.01 and 1");
        assertThatThrownBy(() -> new SahBuilder().costModel(new CostModel(15, 1e9))).hasMessage("Ki must be between 0.001 and 10000, got 1000000000");
        assertThatThrownBy(() -> new SahBuilder().referenceBudget(0)).hasMessageStartingWith("reference budget must be between 1 and 65536");
        assertThatThrownBy(() -> new GeometryBuilder().sphere(null, 1, 2, 8, 0)).hasMessage("segments must be between 3 and 4096, got 2");
    }

    @Test void aSceneFileFieldGetsTheSameWording(@org.junit.jupiter.api.io.TempDir Path dir) throws Exception {
        Path f = dir.resolve("wide.json");
        Files.writeString(f, """
                {"camera": {"eye": [0, 0, 5], "lookAt": [0, 0, 0], "fov": 40, "width": 20000, "height": 10},
                 "objects": []}
                """);
        assertThatThrownBy(() -> PrimitivesReader.readScene(f)).hasMessageEndingWith(
                "$.camera.width: " + Limits.IMAGE_SIDE.requirement() + ", got 20000");
    }

    /** docs/limits.md is the users' copy of the list: it must say what the code enforces. */
    @Test void docsListEveryLimitWithItsRange() throws Exception {
        List<String> rows = Files.readAllLines(Path.of("docs/limits.md")).stream().filter(r -> r.startsWith("| ")).toList();
        for (Limit l : Limits.ALL) {
            String expected = "| " + l.title() + " | " + l.range() + " |";
            assertThat(rows).as("a row of docs/limits.md starting " + expected).anyMatch(r -> r.startsWith(expected));
        }
    }
}
