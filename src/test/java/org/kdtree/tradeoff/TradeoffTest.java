package org.kdtree.tradeoff;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kdtree.accel.BruteForce;
import org.kdtree.accel.TriangleIntersector;
import org.kdtree.cli.Main;
import org.kdtree.generate.Meshes;
import org.kdtree.kdtree.Traverser;
import org.kdtree.measure.RayBatch;
import org.kdtree.measure.RaySet;
import org.kdtree.shape.TriangleMesh;

class TradeoffTest {
    @TempDir Path dir;

    @Test void paretoFrontKeepsOnlyUndominatedVariants() {
        List<Tradeoff.Result> rs = List.of(result("fast-build", 10, 1e5), result("fast-trace", 100, 1e6),
                result("dominated", 120, 5e5), result("balanced", 50, 6e5));
        assertThat(Tradeoff.paretoFront(rs)).containsExactly(true, true, false, true);
    }

    @Test void totalTimeIsBuildPlusTrace() {
        Tradeoff.Result r = result("x", 100, 1e6);     // 1000 triangles, 1e6 rays/s
        assertThat(r.totalMs(10)).isEqualTo(100 + 10.0);
    }

    @Test void rayCheckSumsMatchBruteForce() {
        TriangleMesh m = Meshes.surface(400, 5);
        TriangleIntersector tri = new TriangleIntersector(m);
        var tree = new org.kdtree.kdtree.SahBuilder().build(m);
        for (RaySet set : new RaySet[] {RaySet.primary(m, 30), RaySet.random(m, 500)}) {
            RayBatch.Checksum kd, brute;
            try (RayBatch batch = new RayBatch(2, () -> new Traverser(tree))) {
                kd = batch.trace(set);
            }
            try (RayBatch batch = new RayBatch(1, () -> new BruteForce(tri))) {
                brute = batch.trace(set);
            }
            assertThat(kd.hits()).as(set.name()).isEqualTo(brute.hits()).isPositive();
            assertThat(kd.tSum()).isCloseTo(brute.tSum(), org.assertj.core.data.Offset.offset(1e-9 * brute.tSum()));
        }
    }

    @Test void commandWritesCsvAndChart() throws IOException {
        Path obj = writeObj(Meshes.surface(300, 7));
        Path csv = dir.resolve("out.csv"), png = dir.resolve("out.png");
        int code = Main.run("tradeoff", obj.toString(), "--quick", "--ray-count", "2000", "--runs", "1",
                "--counted-rays", "300", "--csv", csv.toString(), "--chart", png.toString());
        assertThat(code).isZero();
        List<String> lines = Files.readAllLines(csv);
        assertThat(lines).hasSize(1 + Variant.quick().size());
        assertThat(lines.get(0)).startsWith("variant,build_ms,expected_cost");
        assertThat(lines).anyMatch(l -> l.startsWith("sah-exact-l0.8,"));
        assertThat(Files.size(png)).isGreaterThan(1000);
    }

    /** The course example is declared in META-INF/services only: the study lists it, as it would a student's builder. */
    @Test void aBuilderOnTheClassPathIsAVariant() throws IOException {
        assertThat(Variant.all()).anyMatch(v -> v.name().equals("centre-midpoint") && v.spec().builder().equals("centre-midpoint"));
        Path obj = writeObj(Meshes.surface(200, 7));
        Path csv = dir.resolve("cm.csv"), png = dir.resolve("cm.png");
        int code = Main.run("tradeoff", obj.toString(), "--variants", "centre-midpoint", "--ray-count", "1000", "--runs", "1",
                "--counted-rays", "100", "--csv", csv.toString(), "--chart", png.toString(), "--quiet");
        assertThat(code).isZero();
        assertThat(Files.readAllLines(csv)).hasSize(2).anyMatch(l -> l.startsWith("centre-midpoint,"));
    }

    @Test void theBvhsVariantsAreStudiedBesideTheKdTrees() {
        List<Variant> bvh = Variant.all().stream().filter(v -> v.spec().builder().equals("bvh")).toList();
        assertThat(bvh).extracting(Variant::name).containsExactly("bvh", "bvh-width2", "bvh-width8", "bvh-b8", "bvh-leaf1");
        assertThat(Variant.quick()).extracting(Variant::name).contains("bvh", "sah-exact-l0.8");
        assertThat(Variant.all()).extracting(Variant::name).doesNotHaveDuplicates();
    }

    /** The same harness for both structures: the same rays, the same counts, one chart and one CSV. */
    @Test void aBvhIsMeasuredByTheSameHarness() {
        TriangleMesh m = Meshes.surface(300, 7);
        Tradeoff t = new Tradeoff(m, RaySet.random(m, 2000), 1, 1, 300);
        List<Tradeoff.Result> rs = Variant.all().stream().filter(v -> List.of("sah-exact-l0.8", "bvh", "bvh-width8").contains(v.name()))
                .map(t::run).toList();
        Tradeoff.Result kd = rs.get(0), bvh = rs.get(1), wide = rs.get(2);
        assertThat(kd.boxesPerRay()).as("a kd-tree tests no boxes").isZero();
        assertThat(bvh.boxesPerRay()).isPositive();
        assertThat(bvh.testsPerRay()).isPositive();
        assertThat(bvh.settings()).startsWith("width=4 bins=32 leafSize=16");
        assertThat(wide.nodes()).as("the same binary tree, collapsed wider").isEqualTo(bvh.nodes());
        assertThat(wide.expectedCost()).isEqualTo(bvh.expectedCost());
        assertThat(Tradeoff.csv(rs).lines()).anyMatch(l -> l.startsWith("bvh-width8,")).element(0).asString().contains("boxes_per_ray");
        assertThat(TradeoffChart.chart(rs, "t", 10).getSeriesMap()).containsKeys("sah-exact-l0.8", "bvh", "bvh-width8");
    }

    /** Issue 45, item 5: every row names the structure, the loop and the path that traced its rays, both structures alike. */
    @Test void everyRowNamesTheEngineThatTracedIt() {
        TriangleMesh m = Meshes.surface(300, 7);
        for (RaySet rays : new RaySet[] {RaySet.random(m, 500), RaySet.primary(m, 24)}) {
            Tradeoff t = new Tradeoff(m, rays, 1, 1, 100);
            for (String variant : List.of("sah-exact-l0.8", "bvh")) {
                Tradeoff.Result r = t.run(Variant.all().stream().filter(v -> v.name().equals(variant)).findFirst().orElseThrow());
                assertThat(r.engine()).as(variant).startsWith(variant.equals("bvh") ? "bvh; " : "kd-tree; ")
                        .contains(rays.imageWidth() > 0 ? "; 8 x 8 packets" : "; single rays; ");
                assertThat(Tradeoff.csv(List.of(r))).contains("\"" + r.engine() + "\"");
            }
        }
    }

    @Test void theCommandTakesTheBvhAsAnotherVariant() throws IOException {
        Path obj = writeObj(Meshes.surface(200, 7));
        Path csv = dir.resolve("bvh.csv"), png = dir.resolve("bvh.png");
        int code = Main.run("tradeoff", obj.toString(), "--variants", "bvh-b8,bvh-bvh-width-2,sah-exact-l0.8", "-b", "bvh",
                "--bvh-width", "2", "--ray-count", "1000", "--runs", "1", "--counted-rays", "100", "--csv", csv.toString(),
                "--chart", png.toString(), "--quiet");
        assertThat(code).isZero();
        List<String> lines = Files.readAllLines(csv);
        assertThat(lines).hasSize(4);
        assertThat(lines).anyMatch(l -> l.startsWith("bvh-b8,") && l.contains("\"width=2 bins=8"))
                .anyMatch(l -> l.startsWith("bvh-bvh-width-2,") && l.contains("\"width=2 bins=32"))
                .anyMatch(l -> l.startsWith("sah-exact-l0.8,"));
        assertThat(Files.size(png)).isGreaterThan(1000);
    }

    @Test void unknownVariantIsAClearError() throws IOException {
        Path obj = writeObj(Meshes.surface(50, 7));
        assertThat(Main.run("tradeoff", obj.toString(), "--variants", "nonsense")).isEqualTo(2);
    }

    private static Tradeoff.Result result(String name, double buildMs, double raysPerSecond) {
        return new Tradeoff.Result(name, "", buildMs, 1, 1, 1, 1, 1, 1, 0, raysPerSecond, 1000, "test");
    }

    private Path writeObj(TriangleMesh m) throws IOException {
        StringBuilder sb = new StringBuilder();
        double[] v = m.vertices();
        for (int i = 0; i < v.length; i += 3) sb.append(String.format(Locale.ROOT, "v %.17g %.17g %.17g%n", v[i], v[i + 1], v[i + 2]));
        int[] f = m.indices();
        for (int i = 0; i < f.length; i += 3) sb.append("f ").append(f[i] + 1).append(' ').append(f[i + 1] + 1).append(' ').append(f[i + 2] + 1).append('\n');
        Path p = dir.resolve("mesh.obj");
        Files.writeString(p, sb);
        return p;
    }
}
