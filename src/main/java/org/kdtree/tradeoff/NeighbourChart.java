package org.kdtree.tradeoff;

import java.util.ArrayList;
import java.util.List;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYSeries;

/**
 * The accuracy chart of a nearest-neighbour study: recall at k (x) against queries per second
 * (y, log), one line per approximate search (best-bin-first budgets, epsilon values), and the
 * exact kd-tree search and brute force as horizontal reference lines ending at recall 1.
 */
final class NeighbourChart {
    private NeighbourChart() {
    }

    /**
     * The chart itself, for {@link ChartFile#write} (tests read its series and axes).
     *
     * @param results the measurements to draw
     * @param title   the chart's title
     * @return the chart
     */
    static XYChart chart(List<NeighbourStudy.Result> results, String title) {
        XYChart chart = ChartFile.newLogYChart(title, "recall at k (fraction of the true k nearest found)", "queries per second");
        double left = leftEdge(results);
        chart.getStyler().setXAxisMin(left).setXAxisMax(1.0);
        List<XYSeries> series = new ArrayList<>();
        for (NeighbourSearch s : List.of(NeighbourSearch.BEST_BIN_FIRST, NeighbourSearch.EPSILON)) {
            List<NeighbourStudy.Result> rows = results.stream().filter(r -> r.search() == s).toList();
            if (!rows.isEmpty()) series.add(chart.addSeries(s.label(), rows.stream().mapToDouble(NeighbourStudy.Result::recall).toArray(),
                    rows.stream().mapToDouble(NeighbourStudy.Result::queriesPerSecond).toArray()));
        }
        for (NeighbourSearch s : List.of(NeighbourSearch.EXACT, NeighbourSearch.BRUTE_FORCE))
            results.stream().filter(r -> r.search() == s).findFirst().ifPresent(r ->
                    series.add(reference(chart, s.label() + " (exact)", left, r.queriesPerSecond())));
        ChartFile.distinctMarkers(series);
        return chart;
    }

    /** A horizontal line at {@code qps} from the chart's left edge to a marker at recall 1. */
    private static XYSeries reference(XYChart chart, String name, double left, double qps) {
        XYSeries line = chart.addSeries(name, new double[] {left, 1}, new double[] {qps, qps});
        line.setXYSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Line);
        line.setLineStyle(ChartFile.DASHED);
        return line;
    }

    /** The x axis starts at the lowest recall rounded down to a tenth, and shows at least 0.9 .. 1. */
    private static double leftEdge(List<NeighbourStudy.Result> results) {
        double lowest = results.stream().mapToDouble(NeighbourStudy.Result::recall).min().orElse(1);
        return Math.min(0.9, Math.floor(lowest * 10) / 10);
    }
}
