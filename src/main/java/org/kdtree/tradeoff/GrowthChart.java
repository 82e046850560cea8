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
 * <pre>
 * java -cp target/kdtree.jar org.kdtree.tradeoff.GrowthChart growth.png surface naive.csv build.csv ...
 * </pre>
 */
final class GrowthChart {
    private GrowthChart() {
    }

    /**
     * Reads the CSV files and writes the chart for one scene, exiting with 2 on a usage error and
     * 1 if no row is for the scene.
     *
     * @param args the chart to write (PNG or SVG), the scene, then one or more JMH CSV files
     * @throws IOException if a CSV file cannot be read or is not a build benchmark's, or the chart cannot be written
     */
    public static void main(String[] args) throws IOException {
        if (args.length < 3) {
            System.err.println("usage: GrowthChart OUT.png SCENE JMH.csv...");
            System.exit(2);
        }
        String scene = args[1];
        Map<String, TreeMap<Integer, Double>> series = new TreeMap<>();
        for (int i = 2; i < args.length; i++) read(Path.of(args[i]), scene, series);
        if (series.isEmpty()) {
            System.err.println("no rows for scene " + scene + " in " + String.join(", ", List.of(args).subList(2, args.length)));
            System.exit(1);
        }
        String caption = "JMH averages from " + String.join(", ", List.of(args).subList(2, args.length))
                + " · one build thread · drawn " + java.time.LocalDate.now();
        write(series, scene, caption, Path.of(args[0]));
        System.out.println("wrote " + args[0]);
    }

    /** Adds the rows of one JMH CSV whose scene is {@code scene}: builder -> (N -> ms per build). */
    static void read(Path csv, String scene, Map<String, TreeMap<Integer, Double>> series) throws IOException {
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

    static void write(Map<String, TreeMap<Integer, Double>> series, String scene, String caption, Path png) throws IOException {
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
