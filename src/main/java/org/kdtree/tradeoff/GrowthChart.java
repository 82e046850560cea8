package org.kdtree.tradeoff;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.markers.SeriesMarkers;

/**
 * Draws the growth of build time with N from the CSV files JMH writes ({@code -rf csv}) for
 * {@code BuildBenchmark} and {@code NaiveBuildBenchmark} (src/jmh): one log-log line per builder for one
 * scene, with the curves N^2, N log^2 N and N log N drawn through the first point of the naive,
 * sorted and event builds, so that a slope can be read against its prediction.
 *
 * The program that reads the files and writes the chart is {@code bench.GrowthChartFromCsv}
 * (src/jmh, beside the benchmarks whose output it reads).
 */
public final class GrowthChart {
    private GrowthChart() {
    }

    /**
     * Adds the rows of one JMH CSV whose scene is {@code scene}: builder -> (N -> ms per build).
     *
     * @param csv a JMH CSV of a build benchmark
     * @param scene the scene whose rows are read
     * @param series where the rows go, by builder then N
     * @throws IOException if the file cannot be read or is not a build benchmark's
     */
    public static void read(Path csv, String scene, Map<String, TreeMap<Integer, Double>> series) throws IOException {
        List<String> lines = Files.readAllLines(csv);
        if (lines.isEmpty()) return;
        List<String> header = cells(lines.get(0));
        int score = header.indexOf("Score"), builder = header.indexOf("Param: builder");
        int n = header.indexOf("Param: n"), sceneColumn = header.indexOf("Param: scene");
        if (score < 0 || builder < 0 || n < 0 || sceneColumn < 0)
            throw new IOException(csv + ": not a build benchmark CSV (columns Score, Param: builder, n, scene)");
        for (String line : lines.subList(1, lines.size())) {
            List<String> c = cells(line);
            if (c.size() < header.size() || !c.get(sceneColumn).equals(scene)) continue;
            series.computeIfAbsent(c.get(builder), b -> new TreeMap<>())
                    .put(Integer.parseInt(c.get(n)), Double.parseDouble(c.get(score)));
        }
    }

    private static List<String> cells(String line) {
        List<String> out = new ArrayList<>();
        for (String cell : line.split(",", -1)) out.add(cell.replace("\"", "").trim());
        return out;
    }

    /**
     * Writes the chart of {@code series} for one scene.
     *
     * @param series ms per build by builder then N, as {@link #read} fills it
     * @param scene the scene, for the title
     * @param caption the line under the chart
     * @param png the file to write (PNG or SVG)
     * @throws IOException if the chart cannot be written
     */
    public static void write(Map<String, TreeMap<Integer, Double>> series, String scene, String caption, Path png) throws IOException {
        ChartFile.write(chart(series, scene), caption, png);
    }

    /** The chart itself (tests read its series and axes). */
    static XYChart chart(Map<String, TreeMap<Integer, Double>> series, String scene) {
        XYChart chart = ChartFile.newChart("Build time against N (" + scene + " scene, one thread, JMH average)",
                "N (triangles)", "ms per build");
        ChartFile.logAxes(chart);
        chart.getStyler().setLegendPosition(org.knowm.xchart.style.Styler.LegendPosition.InsideNW);
        List<org.knowm.xchart.XYSeries> measured = new ArrayList<>();
        for (Map.Entry<String, TreeMap<Integer, Double>> e : series.entrySet()) {
            TreeMap<Integer, Double> points = e.getValue();
            measured.add(chart.addSeries(e.getKey(), points.keySet().stream().mapToDouble(Integer::doubleValue).toArray(),
                    points.values().stream().mapToDouble(Double::doubleValue).toArray()));
        }
        ChartFile.distinctMarkers(measured);
        reference(chart, series.get("sah-naive"), "N^2 through naive", 2, new java.awt.Color(150, 30, 30));
        reference(chart, series.get("sah-sorted"), "N log^2 N through sorted", 1, new java.awt.Color(150, 110, 0));
        reference(chart, series.get("sah-event"), "N log N through event", 0, new java.awt.Color(0, 110, 0));
        return chart;
    }

    /** The curve N^2 (kind 2), N log^2 N (1) or N log N (0) through the first point of {@code points}. */
    private static void reference(XYChart chart, TreeMap<Integer, Double> points, String name, int kind, java.awt.Color color) {
        if (points == null || points.size() < 2) return;
        double n0 = points.firstKey(), scale = points.firstEntry().getValue() / model(n0, kind);
        double[] x = points.keySet().stream().mapToDouble(Integer::doubleValue).toArray();
        double[] y = new double[x.length];
        for (int i = 0; i < x.length; i++) y[i] = scale * model(x[i], kind);
        XYSeries s = chart.addSeries(name, x, y);
        s.setMarker(SeriesMarkers.NONE);
        s.setLineStyle(org.knowm.xchart.style.lines.SeriesLines.DASH_DASH);
        s.setLineColor(color);
    }

    private static double model(double n, int kind) {
        double log = Math.log(n) / Math.log(2);
        return kind == 2 ? n * n : kind == 1 ? n * log * log : n * log;
    }
}
