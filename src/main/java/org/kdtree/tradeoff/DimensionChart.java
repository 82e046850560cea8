package org.kdtree.tradeoff;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.Styler;

/**
 * The dimension sweep's chart: the exact kd-tree search's speed-up over brute force (y, log)
 * against the dimension (x, linear: on uniform data the speed-up falls about exponentially with
 * it, a straight line here), with the break-even line at 1 where the tree stops helping.
 */
public final class DimensionChart {
    private DimensionChart() {
    }

    /**
     * Writes the chart as PNG or SVG with {@code caption} under it ({@link ChartFile}).
     *
     * @param results the measurements to draw
     * @param title   the chart's title
     * @param caption the text under the chart
     * @param png     the chart file, PNG or SVG ({@link ChartFile#write})
     * @throws IOException if a file cannot be written
     */
    public static void write(List<DimensionResult> results, String title, String caption, Path png) throws IOException {
        ChartFile.write(chart(results, title), caption, png);
    }

    /** The chart itself (tests read its series and axes). */
    static XYChart chart(List<DimensionResult> results, String title) {
        XYChart chart = ChartFile.newChart(title, "dimension", "speed-up of the exact kd-tree search over brute force");
        chart.getStyler().setMarkerSize(9).setLegendPosition(Styler.LegendPosition.OutsideE);
        ChartFile.logYAxis(chart);
        double[] dims = results.stream().mapToDouble(DimensionResult::dimension).toArray();
        List<XYSeries> series = new ArrayList<>();
        series.add(chart.addSeries("exact kd-tree / brute force", dims,
                results.stream().mapToDouble(DimensionResult::speedUp).toArray()));
        double lo = results.stream().mapToInt(DimensionResult::dimension).min().orElse(1);
        double hi = results.stream().mapToInt(DimensionResult::dimension).max().orElse(1);
        XYSeries even = chart.addSeries("break-even (1)", new double[] {lo, hi}, new double[] {1, 1});
        series.add(even);
        ChartFile.distinctMarkers(series);
        even.setLineStyle(ChartFile.DASHED);
        return chart;
    }
}
