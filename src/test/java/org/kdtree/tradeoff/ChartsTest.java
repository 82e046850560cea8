package org.kdtree.tradeoff;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.XYSeries;

/** Every chart the project writes, rendered headless and read back from its model: ticks, markers, caption, files. */
class ChartsTest {
    @TempDir Path dir;

    @Test void logAxesGetTicksAtTwoAndFiveOfEveryDecade() {
        assertThat(ChartFile.intermediateTicks(30, 470)).containsExactly(50.0, 200.0);
        assertThat(ChartFile.intermediateTicks(0.01, 1)).containsExactly(0.02, 0.05, 0.2, 0.5);
        assertThat(ChartFile.intermediateTicks(1000, 100_000)).containsExactly(2000.0, 5000.0, 20_000.0, 50_000.0);
        // less than a decade: at least three labels however narrow the span, never a decade (XChart's own)
        assertThat(ChartFile.intermediateTicks(30, 80)).containsExactly(30.0, 40.0, 50.0, 60.0, 70.0, 80.0);
        assertThat(ChartFile.intermediateTicks(31, 38)).containsExactly(31.0, 32.0, 33.0, 34.0, 35.0, 36.0, 37.0, 38.0);
        assertThat(ChartFile.intermediateTicks(0.42, 0.47)).hasSizeGreaterThanOrEqualTo(3).allMatch(v -> v >= 0.42 && v <= 0.47);
        assertThat(ChartFile.intermediateTicks(90, 110)).containsExactly(90.0, 95.0, 105.0, 110.0);
        assertThat(ChartFile.tickLabel(20)).isEqualTo("20");
        assertThat(ChartFile.tickLabel(0.05)).isEqualTo("0.05");
        assertThat(ChartFile.tickLabel(5000)).isEqualTo("5,000");
        assertThat(ChartFile.tickLabel(2e6)).isEqualTo("2,000,000");
    }

    /**
     * Issue 34, item 11: a log axis's labels are all drawn alike (the decades too, which XChart drew
     * in its own way, lower and larger), over the whole axis, and a point beyond the outermost
     * decade or 2-and-5 tick gets one more round label past it.
     */
    @Test void everyLabelOfALogAxisIsDrawnAlikeAndNoPointStandsBeyondThemAll() {
        // the bunny's R chart: y data 580 .. 7,600 on an axis padded to about 540 .. 8,200
        assertThat(ChartFile.axisTicks(new double[] {540, 8200}, new double[] {580, 7600}))
                .containsExactly(600.0, 1000.0, 2000.0, 5000.0, 8000.0);
        // a round label past the data where the axis has room for one (300 <= 320), none beyond the axis's end (200 > 140)
        assertThat(ChartFile.axisTicks(new double[] {9, 320}, new double[] {10, 260})).containsExactly(10.0, 20.0, 50.0, 100.0, 200.0, 300.0);
        assertThat(ChartFile.axisTicks(new double[] {9, 140}, new double[] {10, 130})).containsExactly(10.0, 20.0, 50.0, 100.0);
        XYChart chart = new XYChartBuilder().width(400).height(300).build();
        ChartFile.logAxes(chart);
        assertThat(chart.getStyler().getAxisTickLabelsColor().getAlpha()).as("XChart's own labels hidden: ChartFile draws them all").isZero();
    }

    @Test void theTradeoffChartHasLabelledLogAxesDistinctMarkersAndUnits() throws Exception {
        List<Tradeoff.Result> results = new ArrayList<>();
        for (int i = 0; i < 12; i++)
            results.add(new Tradeoff.Result("variant-" + i, "", 30 + 40 * i, 100, 1, 1, 1, 1, 1, 0, 1e5 * (1 + i % 5), 1000, "test"));
        XYChart chart = TradeoffChart.chart(results, "test", 10);
        assertLabelledLogAxes(chart, 30, 470, 10, 100);
        assertThat(chart.getXAxisTitle()).contains("(ms)");
        assertThat(chart.getYAxisTitle()).contains("(ms)");
        List<XYSeries> points = chart.getSeriesMap().values().stream()
                .filter(s -> !s.getName().equals("Pareto front")).toList();
        assertDistinct(points);
        assertWritten(chart);
    }

    /** Issue 46, item 9: in the whole study's chart no two variants share a colour (sah-sorted-l0.8 and sah-maxdepth-16 did, both x). */
    @Test void everyVariantOfTheWholeStudyHasAColourOfItsOwn() {
        List<Tradeoff.Result> results = new ArrayList<>();
        for (Variant v : Variant.all())
            results.add(new Tradeoff.Result(v.name(), "", 30 + results.size(), 100, 1, 1, 1, 1, 1, 0, 1e5, 1000, "test"));
        List<XYSeries> points = TradeoffChart.chart(results, "test", 10).getSeriesMap().values().stream()
                .filter(s -> !s.getName().equals("Pareto front")).toList();
        assertThat(points).hasSize(Variant.all().size());
        assertThat(points.stream().map(XYSeries::getMarkerColor).distinct()).hasSameSizeAs(points);
    }

    @Test void theGrowthChartHasLabelledLogAxesAndDistinctMarkers() throws Exception {
        Map<String, TreeMap<Integer, Double>> series = new TreeMap<>();
        for (String b : List.of("sah-event", "sah-sorted", "sah-binned", "sah-naive", "median-plane")) {
            TreeMap<Integer, Double> points = new TreeMap<>();
            for (int n : new int[] {1000, 10_000, 100_000}) points.put(n, n * (1 + b.length() % 3) / 1e4);
            series.put(b, points);
        }
        XYChart chart = GrowthChart.chart(series, "surface");
        assertLabelledLogAxes(chart, 1000, 100_000, 0.1, 2000);   // y: the N^2 reference curve reaches 1000
        assertDistinct(chart.getSeriesMap().values().stream().filter(s -> !s.getName().contains(" through ")).toList());
        assertWritten(chart);
    }

    @Test void theNeighbourChartHasRecallAcrossAndLogQueriesPerSecond() throws Exception {
        List<NeighbourStudy.Result> results = new ArrayList<>();
        results.add(new NeighbourStudy.Result(NeighbourSearch.BRUTE_FORCE, "", 1, 2e3, 0, 1));
        results.add(new NeighbourStudy.Result(NeighbourSearch.EXACT, "", 1, 5e4, 40, 25));
        for (int b = 1; b <= 64; b *= 2)
            results.add(new NeighbourStudy.Result(NeighbourSearch.BEST_BIN_FIRST, "" + b, 1 - 0.4 / b, 4e5 / b, b, 200.0 / b));
        for (double e : new double[] {0.5, 1, 2})
            results.add(new NeighbourStudy.Result(NeighbourSearch.EPSILON, "" + e, 1 - 0.05 * e, 1e5 * e, 10 / e, 50 * e));
        XYChart chart = NeighbourChart.chart(results, "test");
        assertThat(chart.getStyler().isXAxisLogarithmic()).as("recall is a fraction: linear").isFalse();
        assertLogY(chart);
        assertThat(chart.getSeriesMap().keySet()).containsExactly("best-bin-first", "epsilon",
                "exact kd-tree (exact)", "brute force (exact)");
        assertThat(chart.getSeriesMap().get("best-bin-first").getXData()).hasSize(7);
        assertDistinct(List.copyOf(chart.getSeriesMap().values()));
        assertWritten(chart);
    }

    @Test void theDimensionChartHasTheSpeedUpOnALogAxisAndTheBreakEvenLine() throws Exception {
        List<DimensionSweep.Result> results = new ArrayList<>();
        for (int d : new int[] {2, 4, 8, 16, 31}) results.add(new DimensionSweep.Result(d, 1e6 / d / d, 2e4 / d, d * d, 600));
        XYChart chart = DimensionChart.chart(results, "test");
        assertLogY(chart);
        assertThat(chart.getSeriesMap().get("break-even (1)").getYData()).containsOnly(1.0);
        assertDistinct(List.copyOf(chart.getSeriesMap().values()));
        assertWritten(chart);
    }

    /** A log y axis: XChart labels its decades, ChartFile the 2s and 5s between (checked on the data's range). */
    private static void assertLogY(XYChart chart) {
        assertThat(chart.getStyler().isYAxisLogarithmic()).isTrue();
        assertThat(chart.getStyler().isYAxisLogarithmicDecadeOnly()).isTrue();
        double lo = Double.POSITIVE_INFINITY, hi = 0;
        for (XYSeries s : chart.getSeriesMap().values())
            for (double y : s.getYData()) { lo = Math.min(lo, y); hi = Math.max(hi, y); }
        assertThat(ChartFile.intermediateTicks(lo, hi)).hasSizeGreaterThanOrEqualTo(2);
    }

    /**
     * Both axes logarithmic, XChart labelling the decades, and at least two labelled ticks at 2 or
     * 5 of a decade within the data's range on each axis (drawn by ChartFile).
     */
    private static void assertLabelledLogAxes(XYChart chart, double xMin, double xMax, double yMin, double yMax) {
        assertThat(chart.getStyler().isXAxisLogarithmic()).isTrue();
        assertThat(chart.getStyler().isYAxisLogarithmic()).isTrue();
        assertThat(chart.getStyler().isXAxisLogarithmicDecadeOnly()).isTrue();
        assertThat(chart.getStyler().isYAxisLogarithmicDecadeOnly()).isTrue();
        for (XYSeries s : chart.getSeriesMap().values()) {
            for (double x : s.getXData()) assertThat(x).isBetween(xMin, xMax);
            for (double y : s.getYData()) assertThat(y).isBetween(yMin, yMax);
        }
        assertThat(ChartFile.intermediateTicks(xMin, xMax)).hasSizeGreaterThanOrEqualTo(2);
        assertThat(ChartFile.intermediateTicks(yMin, yMax)).hasSizeGreaterThanOrEqualTo(2);
    }

    private static void assertDistinct(List<XYSeries> series) {
        Set<String> looks = new HashSet<>();
        for (XYSeries s : series) looks.add(s.getMarker().getClass().getSimpleName() + "/" + s.getMarkerColor());
        assertThat(looks).as("marker shape and colour per series").hasSize(series.size());
    }

    private void assertWritten(XYChart chart) throws Exception {
        Path png = dir.resolve("chart.png"), svg = dir.resolve("chart.svg");
        ChartFile.write(chart, "the caption line", png);
        BufferedImage image = ImageIO.read(png.toFile());
        assertThat(image.getWidth()).isEqualTo(chart.getWidth());
        assertThat(image.getHeight()).as("the chart plus its caption").isGreaterThan(chart.getHeight());
        assertThat(svg).as("one file per chart").doesNotExist();
        ChartFile.write(chart, "the caption line", svg);
        assertThat(Files.readString(svg)).contains("<svg").contains("the caption line");
        assertThat(Files.list(dir)).as("one file per chart").hasSize(2);
    }
}
