package org.kdtree.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kdtree.accel.BruteForce;
import org.kdtree.accel.Hit;
import org.kdtree.accel.TriangleIntersector;
import org.kdtree.generate.MeshGrid;
import org.kdtree.geom.Box;
import org.kdtree.geom.Ray;
import org.kdtree.io.PrimitivesReader;
import org.kdtree.measure.RaySet;
import org.kdtree.shape.TriangleMesh;

class RaycastCommandTest {
    @TempDir Path dir;

    /** A unit cube with quad faces (fan-triangulated: 12 triangles) in the face forms the SPEC lists. */
    private Path cube() throws Exception {
        Path obj = dir.resolve("cube.obj");
        Files.writeString(obj, String.join("\n",
                "# a cube", "v 0 0 0", "v 1 0 0", "v 1 1 0", "v 0 1 0", "v 0 0 1", "v 1 0 1", "v 1 1 1", "v 0 1 1",
                "vt 0 0", "vn 0 0 1",
                "f 1 4 3 2", "f 5/1 6/1 7/1 8/1", "f 1//1 2//1 6//1 5//1", "f 4/1/1 8/1/1 7/1/1 3/1/1",
                "f -8 -4 -1 -5", "f 2 3 7 6", ""));
        return obj;
    }

    private record Run(int code, String out, String err) {
    }

    private static Run run(String... args) {
        PrintStream out = System.out, err = System.err;
        ByteArrayOutputStream o = new ByteArrayOutputStream(), e = new ByteArrayOutputStream();
        try {
            System.setOut(new PrintStream(o, true, StandardCharsets.UTF_8));
            System.setErr(new PrintStream(e, true, StandardCharsets.UTF_8));
            int code = Main.run(args);
            return new Run(code, o.toString(StandardCharsets.UTF_8), e.toString(StandardCharsets.UTF_8));
        } finally {
            System.setOut(out);
            System.setErr(err);
        }
    }

    @Test void rayFileModeMatchesBruteForceLineByLine() throws Exception {
        Path obj = cube();
        Path rays = dir.resolve("rays.txt"), hits = dir.resolve("hits.txt");
        List<String> lines = List.of(
                "# origin direction [tmin tmax]",
                "0.5 0.5 -1 0 0 1",
                "0.5 0.5 -1 0 0 2",                 // not normalised: t is the ray parameter
                "0.5 0.5 0.5 1 0 0",                 // from inside
                "1 1 -1 0 0 1",                      // through a vertex
                "0.5 0 -1 -0.0 0.0 1",               // along an edge's plane, signed zeros
                "   ",
                "0.5 0.5 -1 0 0 1 1.5 3",            // range skips the near face
                "0.5 0.5 -1 0 0 1 0 0.5",            // range ends before the cube
                "2 2 2 1 1 1");                      // misses
        Files.write(rays, lines);
        for (String builder : List.of("sah", "median-plane", "object-median")) {
            Run r = run("raycast", obj.toString(), "--builder", builder, "--rays", rays.toString(), "--hits", hits.toString());
            assertThat(r.code()).as(r.err()).isZero();
            List<String> got = Files.readAllLines(hits);
            TriangleMesh mesh = PrimitivesReader.readMesh(obj);
            assertThat(mesh.size()).isEqualTo(12);
            BruteForce brute = new BruteForce(new TriangleIntersector(mesh));
            int k = 0;
            Hit h = new Hit();
            for (String line : lines) {
                String s = line.strip();
                if (s.isEmpty() || s.startsWith("#")) continue;
                String[] t = s.split("\\s+");
                double[] v = new double[t.length];
                for (int i = 0; i < t.length; i++) v[i] = Double.parseDouble(t[i]);
                Ray ray = new Ray(3).set(v[0], v[1], v[2], v[3], v[4], v[5]);
                boolean hit = brute.closestHit(ray, t.length > 6 ? v[6] : 0, t.length > 6 ? v[7] : Double.POSITIVE_INFINITY, h);
                String out = got.get(k++);
                if (!hit) {
                    assertThat(out).isEqualTo("miss");
                } else {
                    String[] f = out.split(" ");
                    assertThat(Double.parseDouble(f[0])).as(line).isEqualTo(h.t);
                    assertThat(f[0].replaceAll("[^0-9]", "").length()).isGreaterThanOrEqualTo(9);
                    Hit probe = new Hit();
                    new TriangleIntersector(mesh).intersect(Integer.parseInt(f[1]), ray, 0, Double.POSITIVE_INFINITY, probe);
                    assertThat(probe.t).as("triangle %s equally close", f[1]).isEqualTo(h.t);
                }
            }
            assertThat(got).hasSize(k);
            assertThat(got.get(1)).startsWith("0.5000000");
            assertThat(got.get(k - 2)).isEqualTo("miss");
        }
    }

    @Test void badRayLinesAreReportedWithFileAndLine() throws Exception {
        Path obj = cube();
        Path rays = dir.resolve("bad.txt");
        Files.write(rays, List.of("0 0 0 1 0 0", "# fine", "0 0 0 1 0"));
        Run r = run("raycast", obj.toString(), "--rays", rays.toString(), "--hits", dir.resolve("h.txt").toString());
        assertThat(r.code()).isEqualTo(2);
        assertThat(r.err()).contains("bad.txt:3").contains("got 5 values").doesNotContain("Exception");
        Files.write(rays, List.of("0 0 0 0 0 0"));
        assertThat(run("raycast", obj.toString(), "--rays", rays.toString(), "--hits", "-").err()).contains("bad.txt:1: direction is zero");
        Files.write(rays, List.of("0 0 x 1 0 0"));
        assertThat(run("raycast", obj.toString(), "--rays", rays.toString(), "--hits", "-").err()).contains("bad.txt:1: 'x' is not a number");
        assertThat(run("raycast", obj.toString(), "--rays", rays.toString()).err()).contains("--rays and --hits go together");
        assertThat(run("raycast", dir.resolve("none.obj").toString()).err()).contains("none.obj").contains("no such file");
    }

    @Test void benchmarkLineHasTheSpecFieldsAndBruteForceHitCounts() throws Exception {
        Path obj = cube();
        Run r = run("raycast", obj.toString(), "--runs", "1", "--warmup", "0", "--threads", "2");
        assertThat(r.code()).as(r.err()).isZero();
        String[] f = r.out().strip().split(" ");
        assertThat(f).hasSize(13);
        assertThat(f[0]).isEqualTo("kdtree-sah");
        assertThat(f[1]).isEqualTo("cube");
        assertThat(f[2]).isEqualTo("12");
        TriangleMesh mesh = PrimitivesReader.readMesh(obj);
        long[] counts = bruteForceHits(mesh, RaySet.primary(mesh, RaySet.SPEC_IMAGE), RaySet.random(mesh, RaySet.SPEC_RANDOM_RAYS));
        assertThat(Long.parseLong(f[7])).isEqualTo(counts[0]);
        assertThat(Long.parseLong(f[10])).isEqualTo(counts[1]);
        assertThat(counts[1]).as("every ray from inside a closed cube hits").isEqualTo(RaySet.SPEC_RANDOM_RAYS);
    }

    /** Every figure names its engine: the structure, the loop of each ray set, the path. */
    @Test void theBenchmarkNamesItsStructureLoopsAndPath() throws Exception {
        Path obj = cube();
        Run kd = run("raycast", obj.toString(), "--runs", "1", "--warmup", "0");
        assertThat(kd.code()).as(kd.err()).isZero();
        assertThat(kd.err()).contains("# structure: kd-tree (sah)")
                .contains("# loops: rays not of an image (set R) alone, through the single-ray loop; an image's rays (set P) in 8 x 8 packets, "
                        + "through the packet loop")
                .contains("# path: ");
        Run bvh = run("raycast", obj.toString(), "--runs", "1", "--warmup", "0", "-b", "bvh");
        assertThat(bvh.code()).as(bvh.err()).isZero();
        assertThat(bvh.err()).contains("# structure: bvh (bvh)").contains("in 8 x 8 packets, through the packet loop").contains("# path: ");
        assertThat(bvh.out().split(" ")[7]).as("the same P hits through either structure's packets").isEqualTo(kd.out().split(" ")[7]);
    }

    private static long[] bruteForceHits(TriangleMesh mesh, RaySet... sets) {
        BruteForce brute = new BruteForce(new TriangleIntersector(mesh));
        long[] n = new long[sets.length];
        Ray ray = new Ray(3);
        Hit h = new Hit();
        for (int s = 0; s < sets.length; s++) {
            double[] rs = sets[s].rays();
            for (int o = 0; o < rs.length; o += 6) {
                ray.set(rs[o], rs[o + 1], rs[o + 2], rs[o + 3], rs[o + 4], rs[o + 5]);
                if (brute.closestHit(ray, Double.MIN_VALUE, Double.POSITIVE_INFINITY, h)) n[s]++;
            }
        }
        return n;
    }

    @Test void gridRepeatsTheMeshSixteenTimes() throws Exception {
        TriangleMesh mesh = PrimitivesReader.readMesh(cube());
        TriangleMesh grid = MeshGrid.grid(mesh, 4);
        assertThat(grid.size()).isEqualTo(16 * 12);
        Box b = MeshGrid.vertexBounds(grid);
        assertThat(b.max(0)).isEqualTo(1.1 * 3 + 1);
        assertThat(b.max(1)).isEqualTo(1.0);
        assertThat(b.max(2)).isEqualTo(1.1 * 3 + 1);
        // copy (gx = 1, gz = 2) is copy 6: its triangle 0 is triangle 72, offset by (1.1, 0, 2.2)
        assertThat(grid.corner(72, 0, 0)).isEqualTo(mesh.corner(0, 0, 0) + 1.1);
        assertThat(grid.corner(72, 0, 2)).isEqualTo(mesh.corner(0, 0, 2) + 2.2);
    }
}
