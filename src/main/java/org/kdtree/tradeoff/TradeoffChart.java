package org.kdtree.tradeoff;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.markers.SeriesMarkers;

/** The trade-off chart: build time against trace time per variant, with the Pareto front drawn as a line. */
final class TradeoffChart {
    private TradeoffChart() {
    }

    /**
     * Writes a chart (PNG or SVG) of build time (x) against the time to trace the
     * workload (y), both in ms, with {@code caption} under the chart.
     *
     * @param results         the measurements, one point per variant
     * @param title           the chart's title
     * @param raysPerTriangle the workload: rays traced per triangle of the scene
     * @param caption         the text under the chart
     * @param png             the chart file, PNG or SVG ({@link ChartFile#write})
     * @throws IOException if a file cannot be written
     */
    static void write(List<Tradeoff.Result> results, String title, double raysPerTriangle, String caption, Path png)
            throws IOException {
        ChartFile.write(chart(results, title, raysPerTriangle), caption, png);
    }

    /** The chart itself (tests read its series and axes). */
    static XYChart chart(List<Tradeoff.Result> results, String title, double raysPerTriangle) {
        XYChart chart = ChartFile.newChart(title, "build time (ms)",
                "trace time for " + fmt(raysPerTriangle) + " rays per triangle (ms)");
        chart.getStyler().setDefaultSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Scatter);
        chart.getStyler().setMarkerSize(10);
        ChartFile.logAxes(chart);
        chart.getStyler().setLegendPosition(org.knowm.xchart.style.Styler.LegendPosition.OutsideE);
        List<XYSeries> points = new ArrayList<>();
        for (Tradeoff.Result r : results)
            points.add(chart.addSeries(r.variant(), new double[] {r.buildMs()}, new double[] {r.traceMs(raysPerTriangle)}));
        ChartFile.distinctMarkers(points);
        boolean[] front = Tradeoff.paretoFront(results);
        List<Tradeoff.Result> onFront = new ArrayList<>();
        for (int i = 0; i < front.length; i++) if (front[i]) onFront.add(results.get(i));
        onFront.sort(Comparator.comparingDouble(Tradeoff.Result::buildMs));
        if (!onFront.isEmpty()) {
            XYSeries line = chart.addSeries("Pareto front",
                    onFront.stream().mapToDouble(Tradeoff.Result::buildMs).toArray(),
                    onFront.stream().mapToDouble(r -> r.traceMs(raysPerTriangle)).toArray());
            line.setXYSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Line);
            line.setMarker(SeriesMarkers.NONE);
            line.setLineColor(java.awt.Color.GRAY);
        }
        return chart;
    }

    private static String fmt(double x) {
        return x == Math.rint(x) ? String.valueOf((long) x) : String.valueOf(x);
    }
}
