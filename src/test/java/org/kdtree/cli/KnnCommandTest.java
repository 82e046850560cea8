package org.kdtree.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code knn} end to end: files in, one line per query out, and one line per mistake. */
class KnnCommandTest {
    @TempDir Path dir;

    private Path file(String name, String text) throws Exception {
        Path f = dir.resolve(name);
        Files.writeString(f, text);
        return f;
    }

    /** The worked example of docs/points.md. */
    @Test void theWorkedExample() throws Exception {
        Path points = file("points.csv", "# x,y\n0,0\n1,0\n0,1\n1,1\n5,5\n");
        Path queries = file("queries.csv", "0.4,0.4\n0.5,0\n9,9\n");
        Path out = dir.resolve("out.csv");
        CliRun r = CliRun.of("knn", points.toString(), "--queries", queries.toString(), "--k", "2", "--out", out.toString());
        assertThat(r.code()).as(r.err()).isZero();
        assertThat(Files.readAllLines(out)).containsExactly("0,1", "0,1", "4,3");
        assertThat(r.out().strip()).startsWith("knn: 5 points, 3 queries, 2-D, k 2, builder sliding-midpoint, build ")
                .contains(" ms, query ").endsWith(" ms");

        r = CliRun.of("knn", points.toString(), "--queries", queries.toString(), "--k", "3", "--radius", "1", "--out", out.toString());
        assertThat(r.code()).as(r.err()).isZero();
        // (0.5, 0) is at distance 0.5 from points 0 and 1 and sqrt(1.25) from 2 and 3; (9, 9) is near none
        assertThat(Files.readAllLines(out)).containsExactly("0,1,2", "0,1", "");
    }

    @Test void everyBuilderGivesTheBruteForceAnswer() throws Exception {
        Random rnd = new Random(4);
        StringBuilder pts = new StringBuilder(), qs = new StringBuilder();
        int n = 300, k = 3;
        double[][] p = new double[n][k];
        for (int i = 0; i < n; i++) {
            for (int a = 0; a < k; a++) p[i][a] = rnd.nextInt(5); // a grid: many ties, broken by index
            pts.append(p[i][0]).append(',').append(p[i][1]).append(',').append(p[i][2]).append('\n');
        }
        double[][] q = new double[20][k];
        for (double[] x : q) {
            for (int a = 0; a < k; a++) x[a] = rnd.nextInt(9) / 2.0;
            qs.append(x[0]).append(", ").append(x[1]).append(", ").append(x[2]).append('\n');
        }
        Path points = file("p.csv", pts.toString()), queries = file("q.csv", qs.toString()), out = dir.resolve("o.csv");
        for (String builder : List.of("sliding-midpoint", "median-plane", "object-median", "sah", "centre-midpoint")) {
            CliRun r = CliRun.of("knn", points.toString(), "--queries", queries.toString(), "--k", "7", "--radius", "1.5",
                    "--builder", builder, "--out", out.toString());
            assertThat(r.code()).as(r.err()).isZero();
            List<String> lines = Files.readAllLines(out);
            assertThat(lines).hasSize(q.length);
            for (int j = 0; j < q.length; j++)
                assertThat(lines.get(j)).as(builder + ", query " + j).isEqualTo(bruteForce(p, q[j], 7, 1.5));
        }
    }

    private static String bruteForce(double[][] p, double[] q, int k, double radius) {
        Integer[] order = new Integer[p.length];
        double[] d2 = new double[p.length];
        for (int i = 0; i < p.length; i++) {
            order[i] = i;
            for (int a = 0; a < q.length; a++) d2[i] += (q[a] - p[i][a]) * (q[a] - p[i][a]);
        }
        java.util.Arrays.sort(order, (x, y) -> d2[x] != d2[y] ? Double.compare(d2[x], d2[y]) : Integer.compare(x, y));
        StringBuilder s = new StringBuilder();
        for (int i = 0; i < k && Math.sqrt(d2[order[i]]) <= radius; i++) s.append(i > 0 ? "," : "").append(order[i]);
        return s.toString();
    }

    @Test void kLargerThanThePointsListsThemAll() throws Exception {
        Path points = file("p.csv", "0\n2\n1\n"), queries = file("q.csv", "1.9\n"), out = dir.resolve("o.csv");
        CliRun r = CliRun.of("knn", points.toString(), "--queries", queries.toString(), "--k", "10", "--out", out.toString());
        assertThat(r.code()).as(r.err()).isZero();
        assertThat(Files.readAllLines(out)).containsExactly("1,2,0");
    }

    @Test void mistakesAreOneLineEach() throws Exception {
        Path points = file("p.csv", "0,0\n1,1\n"), q3 = file("q3.csv", "0,0,0\n"), bad = file("bad.csv", "0,0\n1;1\n");
        String out = dir.resolve("o.csv").toString();
        assertError(CliRun.of("knn", points.toString(), "--queries", q3.toString(), "--k", "1", "--out", out),
                "error: " + q3 + ": the queries are 3-D, the points 2-D (" + points + ")");
        assertError(CliRun.of("knn", points.toString(), "--queries", points.toString(), "--k", "0", "--out", out),
                "error: --k must be between 1 and 100000, got 0");
        assertError(CliRun.of("knn", points.toString(), "--queries", points.toString(), "--k", "1", "--radius", "-1", "--out", out),
                "error: --radius must be a finite number >= 0, got -1.0");
        assertError(CliRun.of("knn", bad.toString(), "--queries", points.toString(), "--k", "1", "--out", out),
                "error: " + bad + ":2: a point needs 2 coordinates, as on line 1, got 1");
        assertError(CliRun.of("knn", points.toString(), "--queries", points.toString(), "--k", "1", "--builder", "nope", "--out", out),
                "error: unknown builder 'nope' (known: sah, median-plane, object-median, sliding-midpoint, centre-midpoint)");
        assertError(CliRun.of("knn", points.toString(), "--queries", points.toString(), "--k", "1", "--out", dir.resolve("no/o.csv").toString()),
                "error: --out " + dir.resolve("no/o.csv") + ": the folder " + dir.resolve("no") + " does not exist");
        Path wide = file("wide.csv", "0" + ",0".repeat(64) + "\n");
        assertError(CliRun.of("knn", wide.toString(), "--queries", wide.toString(), "--k", "1", "--out", out),
                "error: the points are 65-D; a kd-tree here holds at most 64 dimensions");
        assertError(CliRun.of("knn", points.toString(), "--k", "1", "--out", out),
                "error: Missing required option: '--queries=FILE' (kdtree knn --help)");
    }

    private static void assertError(CliRun r, String line) {
        assertThat(r.code()).as(r.err()).isEqualTo(Failure.USAGE);
        assertThat(r.err().strip()).isEqualTo(line);
    }
}
