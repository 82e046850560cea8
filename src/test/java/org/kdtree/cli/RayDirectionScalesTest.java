package org.kdtree.cli;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringReader;
import java.io.StringWriter;
import java.util.Locale;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.kdtree.accel.BruteForce;
import org.kdtree.accel.Hit;
import org.kdtree.accel.TriangleIntersector;
import org.kdtree.generate.MeshGrid;
import org.kdtree.geom.Ray;
import org.kdtree.io.SceneFormatException;
import org.kdtree.kdtree.SahBuilder;
import org.kdtree.kdtree.Traverser;
import org.kdtree.shape.TriangleMesh;

/**
 * Issue 23: ray directions of any scale, down to the smallest subnormal, give the brute-force
 * answer (t the ray parameter of the direction as given), or one line refusing a hit whose t no
 * double holds.
 */
class RayDirectionScalesTest {
    private static final TriangleMesh ONE = new TriangleMesh(new double[] {0, 0, 0, 1, 0, 0, 0, 1, 0}, new int[] {0, 1, 2});

    private static String trace(TriangleMesh mesh, String rays) throws IOException {
        StringWriter out = new StringWriter();
        Traverser traverser = new Traverser(new SahBuilder().build(mesh));
        RayFile.trace(new BufferedReader(new StringReader(rays)), "rays.txt", traverser, new PrintWriter(out));
        return out.toString().strip();
    }

    /** The user's report: a direction component of -1e-308 towards the triangle is a hit at t = 1e308, not a miss. */
    @Test void theReportedRayHits() throws IOException {
        assertThat(Double.parseDouble(trace(ONE, "0.2 0.2 1 0 0 -1e-308").split(" ")[0])).isCloseTo(1e308, org.assertj.core.data.Percentage.withPercentage(1e-12));
        assertThat(trace(ONE, "0.2 0.2 1 1e-309 1e-309 -1e-308")).endsWith(" 0");
        assertThat(trace(ONE, "0.2 0.2 1 4.9e-324 -4.9e-324 -1")).isEqualTo("1.0000000000000000 0");
        assertThat(trace(ONE, "0.2 0.2 1 0 0 -1e300")).isEqualTo("1.0000000000000000e-300 0");
        assertThat(trace(ONE, "0.2 0.2 1 0 0 -1e-320  0 1e300")).isEqualTo("miss"); // tmax rescaled with the direction
    }

    /** A hit beyond the largest double cannot be written: one line, naming the file, the line and the field. */
    @Test void aHitWhoseTOverflowsIsRefused() {
        for (String d : new String[] {"-1e-310", "-4.9e-324"})
            assertThatThrownBy(() -> trace(ONE, "# smallest\n0.2 0.2 1 0 0 " + d)).isInstanceOf(SceneFormatException.class)
                    .hasMessageStartingWith("rays.txt:2: the direction (dx dy dz) is so short that the hit's t, about 1e3")
                    .hasMessageEndingWith("is beyond the largest double (1.8e308); give a longer direction");
    }

    /**
     * Random rays through a grid of triangles, their directions scaled by every power of two from
     * 2^-1074 to 2^1000: the tree's answer is brute force's on the same ray (the direction made
     * ordinary by an exact power of two, t scaled back), or the refusal when t overflows.
     */
    @Test void everyScaleGivesTheBruteForceAnswer() throws IOException {
        TriangleMesh mesh = MeshGrid.grid(ONE, 3);
        BruteForce brute = new BruteForce(new TriangleIntersector(mesh));
        Random rnd = new Random(23);
        int hits = 0, refused = 0;
        for (int i = 0; i < 1500; i++) {
            double[] o = {rnd.nextDouble() * 4 - 0.5, rnd.nextDouble() * 2 - 1, rnd.nextDouble() * 4 - 0.5};
            double[] d = {rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian()};
            int power = rnd.nextInt(2075) - 1074;
            for (int a = 0; a < 3; a++) d[a] = Math.scalb(d[a], power);
            if (d[0] == 0 && d[1] == 0 && d[2] == 0) continue;
            String line = String.format(Locale.ROOT, "%s %s %s %s %s %s", o[0], o[1], o[2], d[0], d[1], d[2]);
            String expected = bruteForce(brute, o, d);
            if (expected == null) {
                assertThatThrownBy(() -> trace(mesh, line)).as(line).hasMessageContaining("is beyond the largest double");
                refused++;
            } else {
                assertThat(trace(mesh, line)).as(line).isEqualTo(expected);
                if (!expected.equals("miss")) hits++;
            }
        }
        assertThat(hits).isGreaterThan(50);
        assertThat(refused).isGreaterThan(0);
    }

    /** Brute force on the direction scaled exactly to a largest component in [1, 2); null if t overflows. */
    private static String bruteForce(BruteForce brute, double[] o, double[] d) {
        double largest = Math.max(Math.abs(d[0]), Math.max(Math.abs(d[1]), Math.abs(d[2])));
        int k = 0;
        while (Math.scalb(largest, k) < 1) k++;
        while (Math.scalb(largest, k) >= 2) k--;
        Ray ray = new Ray(o, new double[] {Math.scalb(d[0], k), Math.scalb(d[1], k), Math.scalb(d[2], k)});
        Hit hit = new Hit();
        if (!brute.closestHit(ray, 0, Double.POSITIVE_INFINITY, hit)) return "miss";
        double t = Math.scalb(hit.t, k);
        return Double.isInfinite(t) ? null : String.format(Locale.ROOT, "%.17g %d", t, hit.primitive);
    }
}
