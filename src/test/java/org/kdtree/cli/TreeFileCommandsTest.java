package org.kdtree.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Issue 43, items 3 and 4 on the command line: {@code --save-tree} and {@code --tree} of stats,
 * raycast, render and knn give the answers of the tree built (the statistics, the benchmark's
 * hits and sums, the image, the neighbours), the load time where the build time was, and one
 * line with exit code 2 for every file or option that does not fit.
 */
class TreeFileCommandsTest {
    @TempDir Path dir;

    private static List<String> statistics(String out) {
        return out.lines().filter(l -> !l.contains(" time: ") && !l.startsWith("builder: ") && !l.startsWith("saved the tree")).toList();
    }

    @Test void statsSavesATreeAndLoadsItWithTheSameStatistics() throws Exception {
        for (String builder : new String[] {"sah", "bvh", "median-plane"}) {
            Path tree = dir.resolve(builder + ".kdtree");
            CliRun built = CliRun.of("stats", "scenes/talk-figures.scene2d", "-b", builder, "--save-tree", tree.toString());
            assertThat(built.code()).as(built.err()).isZero();
            assertThat(built.out()).contains("saved the tree in " + tree + " (" + String.format(java.util.Locale.ROOT, "%,d", Files.size(tree)) + " bytes)");
            CliRun loaded = CliRun.of("stats", "scenes/talk-figures.scene2d", "--tree", tree.toString(), "--threads", "2");
            assertThat(loaded.code()).as(loaded.err()).isZero();
            assertThat(loaded.out()).contains("load time: ").doesNotContain("build time").contains("builder: " + builder + " (")
                    .contains(", saved in " + tree);
            assertThat(statistics(loaded.out())).isEqualTo(statistics(built.out()));
        }
    }

    @Test void raycastThroughALoadedTreeHasTheSameHitsAndSumsAndSaysTheLoadTime() throws Exception {
        Path tree = dir.resolve("spheres.kdtree");
        CliRun built = CliRun.of("raycast", "scenes:clustered-spheres", "--runs", "1", "--warmup", "0", "--save-tree", tree.toString());
        assertThat(built.code()).as(built.err()).isZero();
        CliRun loaded = CliRun.of("raycast", "scenes:clustered-spheres", "--runs", "1", "--warmup", "0", "--tree", tree.toString());
        assertThat(loaded.code()).as(loaded.err()).isZero();
        String[] a = built.out().strip().split(" "), b = loaded.out().strip().split(" ");
        for (int col : new int[] {0, 1, 2, 4, 5, 6, 7, 8, 10, 11}) assertThat(b[col]).as("column %d", col).isEqualTo(a[col]);
        assertThat(loaded.err()).contains("# build_ms is the time to load the tree saved in " + tree);
        assertThat(built.err()).doesNotContain("build_ms is the time to load");
    }

    @Test void raycastWithRaysThroughALoadedTreeWritesTheSameHits() throws Exception {
        Path tree = dir.resolve("spheres.kdtree"), rays = dir.resolve("rays.txt"), h1 = dir.resolve("h1.txt"), h2 = dir.resolve("h2.txt");
        Files.writeString(rays, "0 0 -10 0.01 0.02 1\n0.5 0.5 10 0 0 -1\n3 -4 5 -0.3 0.4 -0.5\n");
        assertThat(CliRun.of("raycast", "scenes:clustered-spheres", "-b", "bvh", "--rays", rays.toString(), "--hits", h1.toString(),
                "--save-tree", tree.toString()).code()).isZero();
        CliRun r = CliRun.of("raycast", "scenes:clustered-spheres", "--rays", rays.toString(), "--hits", h2.toString(), "--tree", tree.toString());
        assertThat(r.code()).as(r.err()).isZero();
        assertThat(Files.readAllLines(h2)).isEqualTo(Files.readAllLines(h1));
    }

    @Test void renderThroughALoadedTreeMakesTheSameImage() throws Exception {
        Path tree = dir.resolve("box.kdtree"), a = dir.resolve("a.png"), b = dir.resolve("b.png");
        String[] small = {"--width", "40", "--height", "30", "--spp", "1"};
        CliRun built = CliRun.of(concat(new String[] {"render", "scenes:cornell-box", "-o", a.toString(), "--save-tree", tree.toString()}, small));
        assertThat(built.code()).as(built.err()).isZero();
        CliRun loaded = CliRun.of(concat(new String[] {"render", "scenes:cornell-box", "-o", b.toString(), "--tree", tree.toString()}, small));
        assertThat(loaded.code()).as(loaded.err()).isZero();
        assertThat(loaded.out()).contains("(loaded from " + tree + ", not built)");
        assertThat(Files.readAllBytes(b)).isEqualTo(Files.readAllBytes(a));
    }

    @Test void knnThroughALoadedTreeFindsTheSameNeighbours() throws Exception {
        Path points = dir.resolve("p.csv"), queries = dir.resolve("q.csv"), tree = dir.resolve("p.kdtree");
        java.util.Random rnd = new java.util.Random(5);
        StringBuilder p = new StringBuilder(), q = new StringBuilder();
        for (int i = 0; i < 500; i++) p.append(rnd.nextDouble()).append(',').append(rnd.nextDouble()).append(',').append(rnd.nextDouble()).append('\n');
        for (int i = 0; i < 40; i++) q.append(rnd.nextDouble()).append(',').append(rnd.nextDouble()).append(',').append(rnd.nextDouble()).append('\n');
        Files.writeString(points, p);
        Files.writeString(queries, q);
        Path o1 = dir.resolve("o1.csv"), o2 = dir.resolve("o2.csv");
        CliRun built = CliRun.of("knn", points.toString(), "--queries", queries.toString(), "--k", "5", "--out", o1.toString(), "-b", "sah",
                "--save-tree", tree.toString());
        assertThat(built.code()).as(built.err()).isZero();
        CliRun loaded = CliRun.of("knn", points.toString(), "--queries", queries.toString(), "--k", "5", "--out", o2.toString(), "--tree", tree.toString());
        assertThat(loaded.code()).as(loaded.err()).isZero();
        assertThat(loaded.out()).contains("builder sah, load ");
        assertThat(Files.readAllLines(o2)).isEqualTo(Files.readAllLines(o1)).hasSize(40);
    }

    private static String[] concat(String[] a, String[] b) {
        String[] all = Arrays.copyOf(a, a.length + b.length);
        System.arraycopy(b, 0, all, a.length, b.length);
        return all;
    }

    /** Exit code 2 and one line, which contains {@code part}. */
    private static void oneLine(CliRun r, String part) {
        assertThat(r.code()).as(r.err()).isEqualTo(2);
        assertThat(r.err().strip()).startsWith("error: ").contains(part).doesNotContain("\n").doesNotContain("Exception");
    }

    @Test void everyBadTreeFileOrOptionGetsOneLine() throws Exception {
        Path tree = dir.resolve("t.kdtree");
        assertThat(CliRun.of("stats", "scenes:clustered-spheres", "--save-tree", tree.toString()).code()).isZero();
        byte[] good = Files.readAllBytes(tree);
        Path cut = dir.resolve("cut.kdtree"), flipped = dir.resolve("flipped.kdtree");
        Files.write(cut, Arrays.copyOf(good, good.length / 2));
        byte[] bad = good.clone();
        bad[good.length / 3] ^= 4;
        Files.write(flipped, bad);
        oneLine(CliRun.of("stats", "scenes:clustered-spheres", "--tree", cut.toString()), cut + ": truncated: ");
        oneLine(CliRun.of("raycast", "scenes:clustered-spheres", "--tree", flipped.toString()), flipped + ": damaged: its checksum is ");
        oneLine(CliRun.of("stats", "scenes:cornell-box", "--tree", tree.toString()), "the tree was built over 10,370 triangles (3-D), the scene has 4,440");
        oneLine(CliRun.of("stats", "scenes:clustered-spheres", "--grid", "2", "--tree", tree.toString()), "the scene has 41,480 triangles");
        oneLine(CliRun.of("stats", "scenes:clustered-spheres", "--tree", "scenes/clustered-spheres.obj"),
                "scenes/clustered-spheres.obj: not a tree file (it starts with ");
        oneLine(CliRun.of("stats", tree.toString()), tree + ": is a saved tree (--save-tree), not a scene or point file");
        oneLine(CliRun.of("raycast", tree.toString()), tree + ": is a saved tree (--save-tree)");
        oneLine(CliRun.of("stats", "scenes:clustered-spheres", "--tree", dir.resolve("none.kdtree").toString()), "none.kdtree: no such file");
        oneLine(CliRun.of("stats", "scenes:clustered-spheres", "--tree", tree.toString(), "-b", "bvh"),
                "--tree " + tree + " holds a tree built by sah; the builder options ask for another");
        oneLine(CliRun.of("stats", "scenes:clustered-spheres", "--tree", tree.toString(), "--save-tree", dir.resolve("x").toString()),
                "give one of them");
        oneLine(CliRun.of("stats", "scenes/clustered-spheres.obj", "--save-tree", "scenes/clustered-spheres.obj"),
                "--save-tree scenes/clustered-spheres.obj is SCENE (scenes/clustered-spheres.obj); save the tree elsewhere");
        Path png = dir.resolve("out.png");
        oneLine(CliRun.of("render", "scenes:cornell-box", "-o", png.toString(), "--save-tree", png.toString()),
                "--save-tree " + png + " is -o (" + png + "); save the tree elsewhere");
        oneLine(CliRun.of("stats", "scenes:clustered-spheres", "--save-tree", dir.resolve("no/such/folder/t.kdtree").toString()), "--save-tree ");
        assertThat(Files.readAllBytes(tree)).as("the good file untouched").isEqualTo(good);
    }

    @Test void knnRefusesATreeOfOtherPrimitives() throws Exception {
        Path points = dir.resolve("p.csv"), queries = dir.resolve("q.csv"), tree = dir.resolve("h.kdtree");
        Files.writeString(points, "0,0,0\n1,0,0\n0,1,0\n0,0,1\n");
        Files.writeString(queries, "0,0,0\n");
        assertThat(CliRun.of("stats", "scenes:clustered-spheres", "-b", "bvh", "--save-tree", tree.toString()).code()).isZero();
        oneLine(CliRun.of("knn", points.toString(), "--queries", queries.toString(), "--k", "1", "--out", dir.resolve("o.csv").toString(),
                "--tree", tree.toString()), "the tree was built over 10,370 triangles (3-D), the scene has 4 points (3-D)");
    }
}
