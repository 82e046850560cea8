package org.kdtree.tradeoff;

import java.awt.Color;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.markers.Marker;
import org.knowm.xchart.style.markers.SeriesMarkers;

/** The trade-off chart: build time against trace time per variant, with the Pareto front drawn as a line. */
public final class TradeoffChart {
    private static final Marker[] MARKERS = {SeriesMarkers.CIRCLE, SeriesMarkers.DIAMOND, SeriesMarkers.SQUARE,
            SeriesMarkers.TRIANGLE_UP, SeriesMarkers.TRIANGLE_DOWN, SeriesMarkers.CROSS, SeriesMarkers.PLUS};
    private static final Color[] COLOURS = {new Color(0x1f77b4), new Color(0xff7f0e), new Color(0x2ca02c),
            new Color(0xd62728), new Color(0x9467bd), new Color(0x8c564b), new Color(0xe377c2), new Color(0x7f7f7f),
            new Color(0x17becf)};

    private TradeoffChart() {
    }

    /** Writes a PNG of build time (x) against the time to trace the workload (y), both in ms. */
    public static void write(List<TradeoffResult> results, String title, double raysPerTriangle, Path png) throws IOException {
        XYChart chart = new XYChartBuilder().width(900).height(600).title(title)
                .xAxisTitle("build time (ms)").yAxisTitle("trace time for " + fmt(raysPerTriangle) + " rays per triangle (ms)").build();
        chart.getStyler().setDefaultSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Scatter);
        chart.getStyler().setMarkerSize(10);
        chart.getStyler().setXAxisLogarithmic(true);
        chart.getStyler().setYAxisLogarithmic(true);
        chart.getStyler().setLegendPosition(org.knowm.xchart.style.Styler.LegendPosition.OutsideE);
        for (int i = 0; i < results.size(); i++) {
            TradeoffResult r = results.get(i);
            XYSeries s = chart.addSeries(r.variant(), new double[] {r.buildMs()}, new double[] {r.traceMs(raysPerTriangle)});
            // 7 markers and 9 colours, coprime: no two of up to 63 variants look alike
            s.setMarker(MARKERS[i % MARKERS.length]);
            s.setMarkerColor(COLOURS[i % COLOURS.length]);
        }
        boolean[] front = Tradeoff.paretoFront(results);
        List<TradeoffResult> onFront = new ArrayList<>();
        for (int i = 0; i < front.length; i++) if (front[i]) onFront.add(results.get(i));
        onFront.sort(Comparator.comparingDouble(TradeoffResult::buildMs));
        if (!onFront.isEmpty()) {
            XYSeries line = chart.addSeries("Pareto front",
                    onFront.stream().mapToDouble(TradeoffResult::buildMs).toArray(),
                    onFront.stream().mapToDouble(r -> r.traceMs(raysPerTriangle)).toArray());
            line.setXYSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Line);
            line.setMarker(SeriesMarkers.NONE);
        }
        BitmapEncoder.saveBitmap(chart, png.toString(), BitmapEncoder.BitmapFormat.PNG);
    }

    private static String fmt(double x) {
        return x == Math.rint(x) ? String.valueOf((long) x) : String.valueOf(x);
    }
}
