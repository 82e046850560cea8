package org.kdtree.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kdtree.generate.Points;
import org.kdtree.shape.PointsKd;

/** {@code compare-trees} end to end: the distance and its terms, the CSV, the picture, and one line per mistake. */
class CompareTreesCommandTest {
    @TempDir Path dir;

    static Path csv(Path dir, String name, PointsKd p, double scale, double shift) throws Exception {
        StringBuilder b = new StringBuilder("# generated\n");
        for (int i = 0; i < p.size(); i++) {
            for (int a = 0; a < p.dimension(); a++)
                b.append(a > 0 ? "," : "").append(String.format(Locale.ROOT, "%.17g", p.coord(i, a) * scale + shift * (a + 1)));
            b.append('\n');
        }
        Path f = dir.resolve(name);
        Files.writeString(f, b);
        return f;
    }

    private static double printed(String out, String label) {
        Matcher m = Pattern.compile("(?m)^\\s*" + label + "\\s+([0-9.]+)").matcher(out);
        assertThat(m.find()).as(label + " in " + out).isTrue();
        return Double.parseDouble(m.group(1));
    }

    @Test void twoScenesGiveTheDistanceItsTermsACsvAndAPicture() throws Exception {
        Path csv = dir.resolve("terms.csv"), png = dir.resolve("trees.png");
        CliRun r = CliRun.of("compare-trees", "scenes/uniform-200.scene2d", "scenes/clustered-200.scene2d", "--csv", csv.toString(),
                "--chart", png.toString());
        assertThat(r.code()).as(r.err()).isZero();
        double total = printed(r.out(), "distance");
        assertThat(total).isBetween(0.05, 1.0);
        List<String> rows = Files.readAllLines(csv);
        assertThat(rows).hasSize(6).first().isEqualTo("term,weight,value");
        double weighted = 0;
        for (String row : rows.subList(1, 5)) {
            String[] f = row.split(",");
            assertThat(Double.parseDouble(f[2])).as(row).isCloseTo(printed(r.out(), f[0]), org.assertj.core.data.Offset.offset(1e-4));
            weighted += Double.parseDouble(f[1]) * Double.parseDouble(f[2]);
        }
        assertThat(rows.get(5)).startsWith("total,1,");
        assertThat(weighted).isCloseTo(total, org.assertj.core.data.Offset.offset(1e-4));
        BufferedImage image = ImageIO.read(png.toFile());
        assertThat(image.getWidth()).isGreaterThan(1000);
        // each tree panel shows red split lines, and the difference panel is not blank
        int third = image.getWidth() / 3;
        for (int panel = 0; panel < 3; panel++) {
            int red = 0, coloured = 0;
            for (int y = 100; y < image.getHeight() - 80; y++)
                for (int x = panel * third + 30; x < (panel + 1) * third - 10; x++) {
                    int rgb = image.getRGB(x, y), rr = rgb >> 16 & 255, gg = rgb >> 8 & 255, bb = rgb & 255;
                    if (rr > 150 && gg < 90 && bb < 90) red++;
                    if (rgb != 0xffffffff && Math.abs(rr - gg) + Math.abs(gg - bb) > 30) coloured++;
                }
            assertThat(coloured).as("coloured pixels of panel " + panel).isGreaterThan(5000);
            if (panel < 2) assertThat(red).as("split-line pixels of panel " + panel).isGreaterThan(500);
        }
    }

    @Test void aShiftedAndScaledCopyIsAtZeroAndAnotherPatternIsNot() throws Exception {
        PointsKd p = Points.ring(3000, 5, 0.02, 3);
        Path a = csv(dir, "a.csv", p, 1, 0), b = csv(dir, "b.csv", p, 250, -40), c = csv(dir, "c.csv", Points.uniform(3000, 5, 3), 1, 0);
        CliRun r = CliRun.of("compare-trees", a.toString(), b.toString());
        assertThat(r.code()).as(r.err()).isZero();
        assertThat(r.out()).contains("builder sliding-midpoint").contains("3000 5-D points");
        assertThat(printed(r.out(), "distance")).isZero();
        r = CliRun.of("compare-trees", a.toString(), c.toString(), "-b", "median-plane", "--chart", dir.resolve("p.png").toString());
        assertThat(r.code()).as(r.err()).isZero();
        assertThat(r.out()).contains("builder median-plane");
        assertThat(printed(r.out(), "distance")).isGreaterThan(0.3);
        assertThat(ImageIO.read(dir.resolve("p.png").toFile())).isNotNull();
    }

    @Test void badInputIsOneLine() throws Exception {
        Path two = csv(dir, "two.csv", Points.uniform(50, 2, 1), 1, 0), three = csv(dir, "three.csv", Points.uniform(50, 3, 1), 1, 0);
        Path empty = dir.resolve("empty.csv");
        Files.writeString(empty, "# nothing\n");
        String scene = "scenes/uniform-200.scene2d";
        assertError(CliRun.of("compare-trees", two.toString(), three.toString()),
                "error: B " + three + " is 50 3-D points, A " + two + " 50 2-D points: only data of one kind and dimension compare");
        assertError(CliRun.of("compare-trees", scene, two.toString()),
                "error: B " + two + " is 50 2-D points, A " + scene + " a 2-D scene of 200 shapes: only data of one kind and dimension compare");
        assertError(CliRun.of("compare-trees", two.toString(), dir.resolve("missing.csv").toString()),
                "error: B " + dir.resolve("missing.csv") + ": no such file");
        CliRun r = CliRun.of("compare-trees", empty.toString(), two.toString());
        assertThat(r.code()).isEqualTo(Failure.USAGE);
        assertThat(r.err().strip()).doesNotContain("\n").contains(empty.toString());
        assertError(CliRun.of("compare-trees", two.toString(), two.toString(), "--chart", two.toString()),
                "error: --chart " + two + " is the input A (" + two + "); write the results elsewhere");
        assertError(CliRun.of("compare-trees", two.toString(), dir.toString()), "error: B " + dir + ": is a folder, not a file");
        assertError(CliRun.of("compare-trees", two.toString(), two.toString(), "--leaf-size", "0"),
                "error: --leaf-size must be between 1 and 65536, got 0");
        assertThat(Files.exists(two)).isTrue();
    }

    static void assertError(CliRun r, String line) {
        assertThat(r.code()).as(r.err()).isEqualTo(Failure.USAGE);
        assertThat(r.err().strip()).isEqualTo(line);
    }
}
