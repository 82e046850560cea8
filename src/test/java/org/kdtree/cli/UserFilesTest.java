package org.kdtree.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Issue 23: nothing the user has is lost or mixed. Outputs are written whole or not at all,
 * concurrent runs never mix, and an output that is an input, by any name, is refused before any work.
 */
class UserFilesTest {
    @TempDir Path dir;

    private Path points() throws Exception {
        Random rnd = new Random(23);
        StringBuilder s = new StringBuilder();
        for (int i = 0; i < 2000; i++) s.append(rnd.nextDouble()).append(',').append(rnd.nextDouble()).append('\n');
        return Files.writeString(dir.resolve("pts.csv"), s);
    }

    private Path cube() throws Exception {
        return Files.writeString(dir.resolve("one.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    }

    private List<Path> folder() throws Exception {
        try (Stream<Path> files = Files.list(dir)) {
            return files.map(Path::getFileName).sorted().toList();
        }
    }

    /** The user's report: k = 20 and k = 21 into one file at once. The file is one run's, whole. */
    @Test void twoKnnRunsIntoOneFileNeverMix() throws Exception {
        Path pts = points(), out = dir.resolve("same.csv");
        ExecutorService pool = Executors.newFixedThreadPool(2);
        try {
            for (int round = 0; round < 5; round++) {
                CountDownLatch start = new CountDownLatch(1);
                List<Future<Integer>> codes = new ArrayList<>();
                for (String k : List.of("20", "21"))
                    codes.add(pool.submit(() -> {
                        start.await();
                        return Main.run("knn", pts.toString(), "--queries", pts.toString(), "--k", k, "--out", out.toString());
                    }));
                start.countDown();
                for (Future<Integer> code : codes) assertThat(code.get()).isZero();
                List<Integer> widths = Files.readAllLines(out).stream().map(l -> l.split(",").length).distinct().toList();
                assertThat(widths).as("neighbours per line, round " + round).singleElement().isIn(20, 21);
                assertThat(Files.readAllLines(out)).hasSize(2000);
            }
        } finally {
            pool.shutdownNow();
        }
        assertThat(folder()).containsExactlyInAnyOrder(Path.of("pts.csv"), Path.of("same.csv"));
    }

    @Test void knnRefusesToWriteOverItsInputByAnyName() throws Exception {
        Path pts = points(), queries = Files.writeString(dir.resolve("q.csv"), "0.5,0.5\n");
        byte[] before = Files.readAllBytes(pts);
        Path sub = Files.createDirectory(dir.resolve("sub"));
        Path link = Files.createSymbolicLink(dir.resolve("link.csv"), pts), hard = Files.createLink(dir.resolve("hard.csv"), pts);
        for (Path out : List.of(pts, dir.resolve("./pts.csv"), sub.resolve("../pts.csv"), link, hard)) {
            CliRun r = CliRun.of("knn", pts.toString(), "--queries", queries.toString(), "--k", "2", "--out", out.toString());
            assertThat(r.code()).isEqualTo(Failure.USAGE);
            assertThat(r.err().strip()).isEqualTo("error: --out " + out + " is the input POINTS (" + pts + "); write the results elsewhere");
            assertThat(Files.readAllBytes(pts)).isEqualTo(before);
        }
        CliRun r = CliRun.of("knn", pts.toString(), "--queries", queries.toString(), "--k", "2", "--out", queries.toString());
        assertThat(r.code()).isEqualTo(Failure.USAGE);
        assertThat(r.err().strip()).isEqualTo("error: --out " + queries + " is the input --queries (" + queries
                + "); write the results elsewhere");
    }

    /** The user's report: a bad line 2 left hits.txt as one line of partial output. Now it stays as it was. */
    @Test void aBadRayLineLeavesTheOldHitsFileAsItWas() throws Exception {
        Path obj = cube(), rays = Files.writeString(dir.resolve("short.txt"), "0.2 0.2 -1 0 0 1\n0.2 0.2 -1 0 0\n");
        Path hits = Files.writeString(dir.resolve("hits.txt"), "1 0\nmiss\nmiss\n");
        CliRun r = CliRun.of("raycast", obj.toString(), "--rays", rays.toString(), "--hits", hits.toString());
        assertThat(r.code()).isEqualTo(Failure.USAGE);
        assertThat(r.err()).contains("short.txt:2: expected 'ox oy oz dx dy dz'");
        assertThat(Files.readString(hits)).isEqualTo("1 0\nmiss\nmiss\n");
        assertThat(folder()).containsExactlyInAnyOrder(Path.of("one.obj"), Path.of("short.txt"), Path.of("hits.txt"));
    }

    @Test void raycastRefusesHitsThatAreTheMeshOrTheRays() throws Exception {
        Path obj = cube(), rays = Files.writeString(dir.resolve("rays.txt"), "0.2 0.2 -1 0 0 1\n");
        Path meshLink = Files.createSymbolicLink(dir.resolve("hits-link.txt"), obj);
        CliRun r = CliRun.of("raycast", obj.toString(), "--rays", rays.toString(), "--hits", meshLink.toString());
        assertThat(r.code()).isEqualTo(Failure.USAGE);
        assertThat(r.err().strip()).isEqualTo("error: --hits " + meshLink + " is the input MESH (" + obj + "); write the results elsewhere");
        Path raysHard = Files.createLink(dir.resolve("hits.txt"), rays);
        r = CliRun.of("raycast", obj.toString(), "--rays", rays.toString(), "--hits", raysHard.toString());
        assertThat(r.err().strip()).isEqualTo("error: --hits " + raysHard + " is the input --rays (" + rays + "); write the results elsewhere");
        assertThat(Files.readString(rays)).isEqualTo("0.2 0.2 -1 0 0 1\n");
        assertThat(Files.readString(obj)).startsWith("v 0 0 0");
    }

    @Test void studiesRefuseOutputsThatAreTheirInputs() throws Exception {
        Path obj = cube();
        CliRun r = CliRun.of("tradeoff", obj.toString(), "--csv", obj.toString(), "--quiet");
        assertThat(r.code()).isEqualTo(Failure.USAGE);
        assertThat(r.err().strip()).isEqualTo("error: --csv " + obj + " is the input MESH (" + obj + "); write the results elsewhere");
        Path pts = points(), q = Files.writeString(dir.resolve("q.csv"), "0.5,0.5\n");
        Path svgLink = Files.createSymbolicLink(dir.resolve("chart.svg"), q);
        r = CliRun.of("knn-study", pts.toString(), "--queries", q.toString(), "--k", "1", "--chart", svgLink.toString());
        assertThat(r.code()).isEqualTo(Failure.USAGE);
        assertThat(r.err().strip()).isEqualTo("error: --chart " + svgLink + " is the input --queries (" + q
                + "); write the results elsewhere");
        Path gif = dir.resolve("chart.gif");
        r = CliRun.of("knn-study", pts.toString(), "--queries", q.toString(), "--k", "1", "--chart", gif.toString());
        assertThat(r.code()).isEqualTo(Failure.USAGE);
        assertThat(r.err().strip()).isEqualTo("error: --chart " + gif + ": a chart is written as .png or .svg");
    }

    /** A study stopped midway keeps its finished rows beside the user's file, never in its place. */
    @Test void anUnfinishedStudyKeepsItsRowsInAPartialFile() throws Exception {
        Path csv = Files.writeString(dir.resolve("study.csv"), "the user's old table\n");
        StudyFile table = new StudyFile(csv);
        table.progress("variant,ms\na,1\n");
        table.progress("variant,ms\na,1\nb,2\n");
        assertThat(Files.readString(csv)).isEqualTo("the user's old table\n");
        assertThat(Files.readString(dir.resolve("study.csv.partial"))).isEqualTo("variant,ms\na,1\nb,2\n");
        table.finish("variant,ms\na,1\nb,2\nc,3\n");
        assertThat(Files.readString(csv)).isEqualTo("variant,ms\na,1\nb,2\nc,3\n");
        assertThat(folder()).containsExactly(Path.of("study.csv"));
    }
}
