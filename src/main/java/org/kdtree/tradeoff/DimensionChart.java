package org.kdtree.tradeoff;

import java.util.ArrayList;
import java.util.List;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYSeries;

/**
 * The dimension sweep's chart: the exact kd-tree search's speed-up over brute force (y, log)
 * against the dimension (x, linear: on uniform data the speed-up falls about exponentially with
 * it, a straight line here), with the break-even line at 1 where the tree stops helping.
 */
final class DimensionChart {
    private DimensionChart() {
    }

    /**
     * The chart itself, for {@link ChartFile#write} (tests read its series and axes).
     *
     * @param results the measurements to draw
     * @param title   the chart's title
     * @return the chart
     */
    static XYChart chart(List<DimensionSweep.Result> results, String title) {
        XYChart chart = ChartFile.newLogYChart(title, "dimension", "speed-up of the exact kd-tree search over brute force");
        double[] dims = results.stream().mapToDouble(DimensionSweep.Result::dimension).toArray();
        List<XYSeries> series = new ArrayList<>();
        series.add(chart.addSeries("exact kd-tree / brute force", dims,
                results.stream().mapToDouble(DimensionSweep.Result::speedUp).toArray()));
        double lo = results.stream().mapToInt(DimensionSweep.Result::dimension).min().orElse(1);
        double hi = results.stream().mapToInt(DimensionSweep.Result::dimension).max().orElse(1);
        XYSeries even = chart.addSeries("break-even (1)", new double[] {lo, hi}, new double[] {1, 1});
        series.add(even);
        ChartFile.distinctMarkers(series);
        even.setLineStyle(ChartFile.DASHED);
        return chart;
    }
}
