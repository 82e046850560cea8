package org.kdtree.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code knn-study} end to end on tiny data: the table, the CSV, the chart files, and one line per mistake. */
class KnnStudyCommandTest {
    @TempDir Path dir;

    @Test void aGeneratedStudyWritesTheTableTheCsvAndTheChart() throws Exception {
        Path csv = dir.resolve("s.csv"), png = dir.resolve("s.png");
        CliRun r = CliRun.of("knn-study", "--generate", "clustered", "--n", "400", "--dimension", "4", "--query-count", "20",
                "--k", "5", "--budgets", "1,4,16", "--epsilons", "0.5", "--runs", "1", "--csv", csv.toString(),
                "--chart", png.toString(), "--quiet");
        assertThat(r.code()).as(r.err()).isZero();
        assertThat(r.out()).contains("data: clustered-4d, 400 points, 20 queries, 4-D, k 5, builder sliding-midpoint")
                .contains("brute force").contains("exact kd-tree").contains("best-bin-first 16").contains("epsilon 0.5");
        List<String> lines = Files.readAllLines(csv);
        assertThat(lines).hasSize(1 + 2 + 3 + 1);
        assertThat(lines.get(0)).isEqualTo("search,setting,recall,queries_per_s,leaves_per_query,speed_up");
        assertThat(lines.subList(3, 6)).extracting(l -> l.split(",")[1]).containsExactly("1", "4", "16");
        assertThat(Files.size(png)).isPositive();
        assertThat(dir.resolve("s.svg")).as("one file per chart").doesNotExist();
    }

    @Test void filesInAndADimensionSweep() throws Exception {
        Path points = dir.resolve("p.csv"), queries = dir.resolve("q.csv");
        Files.writeString(points, "0,0\n1,0\n0,1\n1,1\n5,5\n2,2\n");
        Files.writeString(queries, "0.4,0.4\n9,9\n");
        CliRun r = CliRun.of("knn-study", points.toString(), "--queries", queries.toString(), "--k", "2", "--budgets", "1,2",
                "--runs", "1", "--csv", dir.resolve("f.csv").toString(), "--chart", dir.resolve("f.png").toString());
        assertThat(r.code()).as(r.err()).isZero();
        assertThat(Files.readAllLines(dir.resolve("f.csv"))).hasSize(5);

        r = CliRun.of("knn-study", "--dimensions", "2,5", "--n", "300", "--query-count", "10", "--k", "3", "--runs", "1",
                "--csv", dir.resolve("d.csv").toString(), "--chart", dir.resolve("d.svg").toString());
        assertThat(r.code()).as(r.err()).isZero();
        List<String> lines = Files.readAllLines(dir.resolve("d.csv"));
        assertThat(lines.get(0)).isEqualTo("dimension,exact_queries_per_s,brute_force_queries_per_s,speed_up,leaves_per_query,leaves");
        assertThat(lines.subList(1, lines.size())).extracting(l -> l.split(",")[0]).containsExactly("2", "5");
        assertThat(Files.readString(dir.resolve("d.svg"))).contains("<svg").contains("k 3");
        assertThat(dir.resolve("d.png")).doesNotExist();
    }

    @Test void mistakesAreOneLineNamingTheOption() throws Exception {
        String csv = dir.resolve("o.csv").toString();
        assertError(CliRun.of("knn-study", "--generate", "uniform", "--k", "0", "--csv", csv), "error: --k must be between 1 and 100000, got 0");
        assertError(CliRun.of("knn-study", "--generate", "uniform", "--k", "1", "--budgets", "4,0", "--csv", csv),
                "error: --budgets must be between 1 and 1000000000, got 0");
        assertError(CliRun.of("knn-study", "--generate", "uniform", "--k", "1", "--epsilons", "-1", "--csv", csv),
                "error: --epsilons must be between 0 and 1000 (0 = exact), got -1");
        assertError(CliRun.of("knn-study", "--generate", "uniform", "--k", "1", "--dimension", "65", "--csv", csv),
                "error: --dimension must be between 1 and " + org.kdtree.points.PointTree.MAX_DIMENSION + ", got 65");
        assertError(CliRun.of("knn-study", "--dimensions", "2,0", "--k", "1", "--csv", csv),
                "error: --dimensions must be between 1 and " + org.kdtree.points.PointTree.MAX_DIMENSION + ", got 0");
        assertError(CliRun.of("knn-study", "--generate", "gaussian", "--k", "1", "--csv", csv),
                "error: --generate must be uniform or clustered, got 'gaussian'");
        assertError(CliRun.of("knn-study", "--k", "1", "--csv", csv),
                "error: give POINTS and --queries FILE, or --generate uniform|clustered");
        assertError(CliRun.of("knn-study", "--generate", "uniform", "--n", "0", "--k", "1", "--csv", csv),
                "error: --n must be between 1 and 50000000, got 0");
        assertError(CliRun.of("knn-study", "--generate", "uniform", "--k", "1", "--csv", dir.resolve("no/o.csv").toString()),
                "error: --csv " + dir.resolve("no/o.csv") + ": the folder " + dir.resolve("no") + " does not exist");
    }

    private static void assertError(CliRun r, String line) {
        assertThat(r.code()).as(r.err()).isEqualTo(Failure.USAGE);
        assertThat(r.err().strip()).isEqualTo(line);
    }
}
