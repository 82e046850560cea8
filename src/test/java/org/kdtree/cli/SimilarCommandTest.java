package org.kdtree.cli;

import static org.assertj.core.api.Assertions.assertThat;
import static org.kdtree.cli.CompareTreesCommandTest.assertError;
import static org.kdtree.cli.CompareTreesCommandTest.csv;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kdtree.generate.Points;

/**
 * {@code similar} end to end: a folder of point sets of three families ranked against an
 * instance of one, the signatures kept in the cache and made again when a file changes, and
 * what is skipped (other kinds, other dimensions, broken files) said.
 */
class SimilarCommandTest {
    @TempDir Path dir;

    @Test void theNearestSetsAreOfTheQuerysFamilyAndTheCacheFollowsTheFiles() throws Exception {
        Path data = Files.createDirectory(dir.resolve("data")), cache = dir.resolve("cache");
        for (int i = 0; i < 3; i++) {
            csv(data, "ring-" + i + ".csv", Points.ring(1500, 2, 0.02, i), 1 + i, 10 * i);
            csv(data, "line-" + i + ".csv", Points.line(1500, 2, 0.02, i), 3 - i, -5 * i);
            csv(data, "uniform-" + i + ".csv", Points.uniform(1500, 2, i), 0.5 + i, i);
        }
        Path query = csv(dir, "query.csv", Points.ring(1500, 2, 0.02, 99), 7, 3);
        csv(data, "ring-3d.csv", Points.ring(1500, 3, 0.02, 5), 1, 0);   // another dimension
        Files.writeString(data.resolve("broken.csv"), "1,2\n3,x\n");      // unreadable
        Files.writeString(data.resolve("notes.txt"), "not data\n");       // another kind
        Files.copy(Path.of("scenes/uniform-200.scene2d"), data.resolve("scene.scene2d"));

        Path ranking = dir.resolve("ranking.csv");
        CliRun r = CliRun.of("similar", query.toString(), data.toString(), "--top", "3", "--cache", cache.toString(), "--csv", ranking.toString());
        assertThat(r.code()).as(r.err()).isZero();
        List<String> top = r.out().lines().filter(l -> l.matches("\\s*\\d+\\s+[0-9.]+\\s+.*")).toList();
        assertThat(top).hasSize(3).allSatisfy(l -> assertThat(l).contains("ring-").doesNotContain("3d"));
        assertThat(r.out()).contains("against 9 data sets").contains("0 from the cache, 11 made")
                .contains("skipped: 2 of another kind, 1 of other data, 1 unreadable");
        assertThat(r.err()).contains("ring-3d.csv").contains("broken.csv:2");
        assertThat(r.err().lines().count()).isEqualTo(2);
        List<String> rows = Files.readAllLines(ranking);
        assertThat(rows).hasSize(10).first().isEqualTo("rank,distance,volumes,splits,depths,occupancy,file");

        CliRun again = CliRun.of("similar", query.toString(), data.toString(), "--top", "3", "--cache", cache.toString());
        assertThat(again.out()).contains("11 from the cache, 0 made");
        assertThat(again.out().lines().filter(l -> l.contains("ring-")).toList()).isEqualTo(top);

        csv(data, "ring-0.csv", Points.uniform(1500, 2, 42), 1, 0);   // the file changes: its signature is made again
        CliRun changed = CliRun.of("similar", query.toString(), data.toString(), "--top", "9", "--cache", cache.toString());
        assertThat(changed.out()).contains("10 from the cache, 1 made");
        String last = changed.out().strip().lines().reduce((a, b) -> b).orElseThrow();
        assertThat(changed.out().lines().filter(l -> l.contains("ring-0.csv")).findFirst().orElseThrow())
                .doesNotStartWith("  1 ").doesNotStartWith("  2 ");
        assertThat(last).doesNotContain("ring-");
    }

    @Test void aCacheThatCannotBeWrittenIsSaidOnceAndTheSearchGoesOn() throws Exception {
        Path data = Files.createDirectory(dir.resolve("data"));
        for (int i = 0; i < 3; i++) csv(data, "u" + i + ".csv", Points.uniform(300, 2, i), 1, 0);
        Path query = csv(dir, "q.csv", Points.uniform(300, 2, 9), 1, 0), notAFolder = dir.resolve("cache-file");
        Files.writeString(notAFolder, "a file where the cache folder should be\n");
        CliRun r = CliRun.of("similar", query.toString(), data.toString(), "--cache", notAFolder.toString());
        assertThat(r.code()).as(r.err()).isZero();
        assertThat(r.err().lines().toList()).singleElement().asString().startsWith("similar: note: cannot keep signatures in " + notAFolder);
        assertThat(r.out()).contains("against 3 data sets").contains("0 from the cache, 4 made");
        assertThat(Files.readString(notAFolder)).startsWith("a file where");
    }

    @Test void badInputIsOneLine() throws Exception {
        Path query = csv(dir, "q.csv", Points.uniform(100, 2, 1), 1, 0);
        assertError(CliRun.of("similar", query.toString(), dir.resolve("nowhere").toString()),
                "error: FOLDER " + dir.resolve("nowhere") + ": no such folder");
        assertError(CliRun.of("similar", query.toString(), query.toString()), "error: FOLDER " + query + ": not a folder");
        assertError(CliRun.of("similar", query.toString(), dir.toString(), "--top", "0"), "error: --top must be between 1 and 100000, got 0");
        assertError(CliRun.of("similar", dir.resolve("none.csv").toString(), dir.toString()), "error: QUERY " + dir.resolve("none.csv") + ": no such file");
    }
}
